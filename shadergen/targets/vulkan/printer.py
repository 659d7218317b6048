"""The GLSL printer (targets/glsl/printer.py) for Vulkan GLSL, which differs in one thing: a texture.

Vulkan GLSL may bind a combined `sampler2D`, but WebGPU, which draws our SPIR-V here (naga reads
it), binds a texture and a sampler apart, as WGSL does. So a library's `sampler2D` parameter is
written as a `texture2D` and a `sampler` (`<name>_sampler`, a suffix no document name takes:
targets/names.py), every call passes both, and a built-in texture call combines them where it
reads: `texture(sampler2D(tex, tex_sampler), uv)`, the only place GL_KHR_vulkan_glsl lets a
combined sampler be made.

glslangValidator writes invalid SPIR-V (KhronosGroup/glslang#3557, open) when an argument after
that combined sampler branches (`?:`): the OpSampledImage lands in another block than its use,
which spirv-val refuses. In a texture call's arguments a selection is therefore written as GLSL
4.50's selecting `mix(if_false, if_true, condition)` (an OpSelect); the library's texture
coordinates have no side effects, so evaluating both sides changes nothing.

A constant array (the libraries' albedo and DFG tables, 256 to 1024 floats) is declared as a
module-scope variable with its values, not `const`: glslang writes a `const` array as a SPIR-V
constant, and since SPIR-V cannot index a value, it copies the whole table into a function-local
variable at every run-time index (12 copies in a lit standard_surface), which lavapipe took over
14 minutes to compile. A variable (SPIR-V's Private storage, as WGSL's `var<private>`,
wgsl/printer.py) is indexed in place.

A section on GL_ES takes its ESSL side, as WGSL's printer does: naga has no OpImageQueryLod
(`textureQueryLod`), so the level of detail comes from the derivatives there too. Every other
section stays a preprocessor section.
"""
from ...code import ir
from ...code.passes.rewrite import rebuild_list
from ...code.types import is_array, is_matrix, scalar_of, size_of
from ..glsl.printer import GlslPrinter, unsupported

TEXTURE = "sampler2D"


def sampler_name(texture: ir.Name) -> ir.Name:
    return ir.Name(texture.name + "_sampler", texture.kind, type="sampler")


class VulkanPrinter(GlslPrinter):
    __slots__ = ()

    def parameters(self, p: ir.Param) -> list[str]:
        if p.type != TEXTURE:
            return [self.parameter(p)]
        name = p.name if self.spell is None else self.spell(ir.Name(p.name, "param"))
        return [f"texture2D {name}", f"sampler {name}_sampler"]

    def call_arguments(self, e: ir.Call) -> list:
        if e.callee is None:  # a built-in: a texture read takes the texture and its sampler combined
            if e.args and e.args[0].type == TEXTURE:
                texture = self.texture_name(e.args[0])
                return [ir.Construct(TEXTURE, [texture, sampler_name(texture)]),
                        *rebuild_list(list(e.args[1:]), expression=selecting_mix)]
            return e.args
        args = []
        for p, a in zip(e.callee.params, e.args):
            if p.type == TEXTURE:
                texture = self.texture_name(a)
                args += [texture, sampler_name(texture)]
            else:
                args.append(a)
        return args

    def constant_qualifier(self, item: ir.Constant) -> str:
        return "" if is_array(item.type) else "const "

    def section(self, s: ir.Section, body_lines, lines: list[str]) -> None:
        if s.macro != "GL_ES":
            super().section(s, body_lines, lines)
        else:  # taken as defined
            lines.extend(body_lines(s.body if s.defined else (s.other or [])))

    @staticmethod
    def texture_name(e) -> ir.Name:
        if type(e) is not ir.Name:
            raise unsupported("a texture argument that is not a name", e)
        return e


def selecting_mix(e):
    """A numeric `c ? a : b` as `mix(b, a, c)` (a vector's condition spread as a bvecN)."""
    if type(e) is not ir.Select or e.type is None or is_matrix(e.type) or scalar_of(e.type) not in NUMERIC:
        return e
    n = size_of(e.type)
    condition = e.condition if n == 1 else ir.Construct(f"bvec{n}", [e.condition])
    return ir.Call("mix", [e.if_false, e.if_true, condition], builtin=True, type=e.type)


NUMERIC = frozenset({"float", "int", "uint"})
