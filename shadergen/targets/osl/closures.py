"""OSL's closure convention: BSDF, EDF and VDF nodes are OSL closures (the MaterialX closures OSL
1.13's stdosl.h declares), which the renderer integrates; no light loop, no evaluated lobes."""
from ..closures import ClosureConvention


class OslClosureConvention(ClosureConvention):
    def output_closure(self, ctx, name: str) -> bool:
        return False
