"""The implementation of OpenColorIO's transform nodes (cms/ocio.py): OCIO's own GLSL of the
transform, read by our library parser into the IR, so every target prints it.

The function is written once per shader and transform, named by the shader's namer
(`cm_<source>_to_<working>`), its helpers and LUT textures prefixed with that name (OCIO's
resource prefix); the textures are private uniforms, their texels in the record's `luts`.
"""
from ..code import build
from ..code import ir
from ..errors import ShaderGenError
from .base import NodeImpl, register


@register("IM_ocio_transform_color3", "IM_ocio_transform_color4")
class OcioTransform(NodeImpl):
    fixed_inputs = frozenset({"transform"})  # which transform: a setting, never a uniform

    @property
    def transform(self):
        from ..cms.ocio import TRANSFORMS
        found = TRANSFORMS.get(self.element.get("transform"))
        if found is None:
            raise ShaderGenError("internal_error", "an OCIO transform was forgotten before its shader was written",
                                 self.element.get("transform"))
        return found

    @property
    def uses_derivatives(self) -> bool:
        return self.transform.has_luts  # texture() with implicit derivatives: kept in uniform flow

    def emit_function_definition(self, node, ctx) -> None:
        transform = self.transform
        key = ("ocio_transform", transform.key)
        if key in ctx.memo:
            return
        if transform.has_luts and not getattr(ctx.target, "functions_see_uniforms", True):
            # OCIO's LUT functions read their textures as globals of the shader; OCIO's own OSL
            # generator refuses these transforms too ("The Lut1DOp is not yet supported")
            raise ShaderGenError("unsupported_colorspace", f"the transform from '{transform.source}' to "
                                 f"'{transform.working}' reads LUT textures, which {ctx.target.name} cannot give "
                                 "OCIO's functions (OCIO's own OSL generator refuses it too); spaces with analytic "
                                 "transforms work", node.path)
        ctx.memo[key] = function = ctx.namer(f"cm_{transform.slug}")
        text, luts = transform.shader(function)
        from ..code.parse import parse_module  # (an OCIO transform's source only: not on every start)
        module = parse_module(f"OCIO {transform.source} -> {transform.working}", text)
        textures = {lut.name: lut for lut in luts}
        for item in module.items:
            if isinstance(item, ir.Global) and item.kind == "uniform" and item.name in textures:
                ctx.private_uniform(item.name, "filename")
                ctx.luts[item.name] = textures[item.name].record()
            elif isinstance(item, ir.Function):
                ctx.namer.used.add(item.name)  # OCIO's helper names: no fresh name of ours takes one
                ctx.add_function(item)
            else:
                raise ShaderGenError("unsupported_colorspace", f"OCIO's shader for '{transform.source}' declares "
                                     f"{type(item).__name__} '{getattr(item, 'name', '')}', which is not taken",
                                     node.path)

    def emit_function_call(self, node, ctx) -> None:
        function = ctx.memo[("ocio_transform", self.transform.key)]
        value = ctx.value(node.inputs["in"])
        if node.inputs["in"].type == "color3":  # OCIO's function takes and gives RGBA
            ctx.assign(node.outputs["out"], build.field(build.call(function, build.construct(
                "vec4", value, build.number(1.0))), "rgb"))
        else:
            ctx.assign(node.outputs["out"], build.call(function, value))
