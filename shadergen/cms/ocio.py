"""Colour management by OpenColorIO: any colour space of a config, its code from OCIO itself.

A config is a file path or an `ocio://NAME` of OCIO's built-in configs (`ocio://default` is the
CG config); colour-space names resolve as OCIO resolves them (names, aliases, roles). A pair of
spaces becomes an `ocio_transform` node whose implementation (nodes/colortransform.py) takes its
code from OCIO's GPU shader generator (GLSL 4.0, the function and its resources named into our
namespace), which our library parser reads into the IR (code/parse.py): every target prints that
one source. OCIO's 1D LUTs are 2D textures (private uniforms; their texels travel in the record's
`luts`, lut_record). Constant inputs fold through OCIO's CPU processor (evaluate.REGISTERED), and
thumbnails go from the working space to the config's default display and view (display_processor).

Transforms are kept per process in TRANSFORMS by their key, the string a node's `transform` input
holds (and so the graph hash): source, working space and the config's identity.
"""
import base64
import os

from ..element import Element
from ..errors import ShaderGenError
from .. import evaluate

try:
    import PyOpenColorIO as OCIO
except ImportError:  # the optional extra (pyproject's `ocio`)
    OCIO = None

COLOR_TYPES = ("color3", "color4")
SHADER_LANGUAGE = "GLSL_4_0"  # the dialect our library parser reads; every target prints its IR
MAX_CONFIGS = 16  # configs kept per process (a service is asked for a few)
MAX_TRANSFORMS = 4096


def _definitions(type_name: str) -> Element:
    zero = "0.0, 0.0, 0.0" if type_name == "color3" else "0.0, 0.0, 0.0, 1.0"
    nodedef = Element("nodedef", {"name": f"ND_ocio_transform_{type_name}", "node": "ocio_transform",
                                  "nodegroup": "colortransform"})
    nodedef.add_child(Element("input", {"name": "in", "type": type_name, "value": zero}))
    nodedef.add_child(Element("input", {"name": "transform", "type": "string", "value": "", "uniform": "true"}))
    nodedef.add_child(Element("output", {"name": "out", "type": type_name}))
    return nodedef


# The transform node's definition: ours, not the library's (no document names it), made once.
NODEDEFS = {t: _definitions(t) for t in COLOR_TYPES}


class Lut:
    """A LUT OCIO's shader samples: a 2D texture of `channels` (1: red, 3: rgb) float texels."""
    __slots__ = ("name", "width", "height", "channels", "linear", "values")

    def __init__(self, name: str, width: int, height: int, channels: int, linear: bool, values: bytes):
        self.name, self.width, self.height, self.channels, self.linear, self.values = \
            name, width, height, channels, linear, values

    def record(self) -> dict:
        """What the record's `luts` holds for it: renderers upload the texels as a float texture."""
        return {"width": self.width, "height": self.height, "channels": self.channels,
                "filter": "linear" if self.linear else "nearest", "format": "float32",
                "data": base64.b64encode(self.values).decode("ascii")}


class Transform:
    """One conversion of a config: its processors, its shader code and its values on the CPU."""

    def __init__(self, cms: "OcioCMS", source: str, working: str, key: str):
        self.cms, self.source, self.working, self.key = cms, source, working, key
        processor = cms.config.getProcessor(source, working)
        self.cpu = processor.getDefaultCPUProcessor()
        self.gpu = processor.getDefaultGPUProcessor()
        self.implementations = {t: Element("implementation", {
            "name": f"IM_ocio_transform_{t}", "nodedef": NODEDEFS[t].name, "target": "genglsl", "transform": key})
            for t in COLOR_TYPES}
        self._shaders: dict[str, tuple[str, list[Lut]]] = {}
        self.has_luts = bool(self.shader("probe")[1])

    def shader(self, function: str) -> tuple[str, list[Lut]]:
        """OCIO's GLSL of the transform as `vec4 function(vec4)`, its helpers and textures
        prefixed `function_`, and the LUTs it samples."""
        if function not in self._shaders:
            desc = OCIO.GpuShaderDesc.CreateShaderDesc(language=getattr(OCIO, f"GPU_LANGUAGE_{SHADER_LANGUAGE}"),
                                                       functionName=function, resourcePrefix=f"{function}_",
                                                       pixelName="color")
            desc.setAllowTexture1D(False)  # 1D LUTs as 2D textures: every target has those
            self.gpu.extractGpuShaderInfo(desc)
            if list(desc.get3DTextures()) or list(desc.getUniforms()):
                raise ShaderGenError("unsupported_colorspace", f"the transform from '{self.source}' to "
                                     f"'{self.working}' needs a 3D LUT or dynamic properties, which targets do not "
                                     f"take yet (config {self.cms.spec})", self.source)
            luts = [Lut(t.samplerName, t.width, t.height,
                        1 if t.channel == OCIO.GpuShaderDesc.TEXTURE_RED_CHANNEL else 3,
                        t.interpolation != OCIO.INTERP_NEAREST, t.getValues().astype("<f4").tobytes())
                    for t in desc.getTextures()]
            self._shaders[function] = (desc.getShaderText(), luts)
        return self._shaders[function]

    def apply(self, value: tuple) -> tuple:
        """The transform of one colour on the CPU (float32, as OCIO computes it)."""
        if len(value) == 3:
            return tuple(self.cpu.applyRGB(list(value)))
        return tuple(self.cpu.applyRGBA(list(value)))

    @property
    def slug(self) -> str:
        """A readable identifier part for the function's name (cm_srgb_texture_to_acescg)."""
        return f"{_slug(self.source)}_to_{_slug(self.working)}"


def _slug(name: str) -> str:
    out = "".join(c.lower() if c.isalnum() else "_" for c in name)
    return "_".join(p for p in out.split("_") if p) or "space"


TRANSFORMS: dict[str, Transform] = {}
CONFIGS: dict[tuple, "OcioCMS"] = {}


class OcioCMS:
    name = "ocio"

    def __init__(self, spec: str, config):
        self.spec, self.config = spec, config
        self.identity = f"ocio {spec} {config.getCacheID()}"  # the config's content, for the cache key
        self._display_processors = {}  # (working, display, view) -> CPU processor: a render worker's every job

    @classmethod
    def for_config(cls, spec: str) -> "OcioCMS":
        """The system of a config, loaded once per process (a file's by its path and version)."""
        if OCIO is None:
            raise ShaderGenError("missing_dependency", "OpenColorIO is not installed (pip install opencolorio, or "
                                 "this package's `ocio` extra)", "cms")
        key = (spec,)
        if not spec.startswith("ocio://"):
            try:
                st = os.stat(spec)
            except OSError as e:
                raise ShaderGenError("invalid_ocio_config", f"OCIO config '{spec}' cannot be read: {e.strerror}",
                                     "ocio_config") from None
            key = (os.path.realpath(spec), st.st_mtime_ns, st.st_size)
        found = CONFIGS.get(key)
        if found is None:
            try:
                config = OCIO.Config.CreateFromFile(spec)
                config.validate()
            except Exception as e:  # OCIO raises its own Exception for every kind of bad config
                raise ShaderGenError("invalid_ocio_config", f"OCIO config '{spec}': {e}", "ocio_config") from None
            if len(CONFIGS) >= MAX_CONFIGS:
                CONFIGS.clear()
            CONFIGS[key] = found = cls(spec, config)
        return found

    def resolve(self, space: str) -> str | None:
        """The config's name of a colour space, alias or role (None: the config lacks it)."""
        found = self.config.getColorSpace(space)
        return found.getName() if found is not None else None

    def require(self, space: str, role: str, where: str) -> str:
        name = self.resolve(space)
        if name is None:
            raise ShaderGenError("unknown_colorspace", f"{role} colour space '{space}' of {where or 'the document'} "
                                 f"is not in the OCIO config '{self.spec}'", where)
        return name

    def transform_for(self, source: str, working: str) -> Transform | None:
        """The transform from `source` to `working` (config names), or None where OCIO does
        nothing (the same space, a data space such as Raw)."""
        key = f"{source} -> {working} in {self.identity}"
        found = TRANSFORMS.get(key)
        if found is None:
            if self.config.getProcessor(source, working).isNoOp():
                return None
            if len(TRANSFORMS) >= MAX_TRANSFORMS:
                TRANSFORMS.clear()
            TRANSFORMS[key] = found = Transform(self, source, working, key)
        return found

    def transform(self, builder, name: str, source: str | None, working: str | None, type_name: str, where: str):
        """A transform node from `source` to the working space, or None; an unknown space of either
        is an `unknown_colorspace` error (never a value used as is)."""
        if not working or not source or type_name not in COLOR_TYPES:
            return None
        working_name = self.require(working, "working", builder.doc_root.path or where)
        transform = self.transform_for(self.require(source, "source", where), working_name)
        if transform is None:
            return None
        node = builder.new_node(name, "ocio_transform", "", NODEDEFS[type_name],
                                transform.implementations[type_name], None)
        node.path = where  # errors name the input the transform serves
        node.inputs["transform"].value = transform.key
        return node

    def display_encoder(self, working: str | None, display: str | None = None, view: str | None = None):
        """fn(linear (h, w, 3) float32 image in the working space) -> the display's encoded values,
        through OCIO's CPU processor of the config's display and view (its default display and that
        display's default view unless named): what a colour-managed viewer shows. No working
        space: the config's scene_linear role. An unknown display or view is an `unknown_view`
        error that lists the config's."""
        display = display or self.config.getDefaultDisplay()
        if display not in self.config.getDisplays():
            raise ShaderGenError("unknown_view", f"no display '{display}' in the OCIO config '{self.spec}'; its "
                                 "displays: " + ", ".join(self.config.getDisplays()), "display")
        views = list(self.config.getViews(display))
        view = view or self.config.getDefaultView(display)
        if view not in views:
            raise ShaderGenError("unknown_view", f"no view '{view}' of display '{display}' in the OCIO config "
                                 f"'{self.spec}'; its views: " + ", ".join(views), "view")
        source = self.require(working or "scene_linear", "working", "the document")
        key = (source, display, view)
        cpu = self._display_processors.get(key)
        if cpu is None:
            try:
                cpu = self.config.getProcessor(OCIO.DisplayViewTransform(src=source, display=display, view=view)) \
                    .getDefaultCPUProcessor()
            except Exception as e:
                raise ShaderGenError("unknown_view", f"display '{display}' / view '{view}' of the OCIO config "
                                     f"'{self.spec}': {e}", "view") from None
            self._display_processors[key] = cpu

        def encode(rgb):
            import numpy as np

            out = np.ascontiguousarray(rgb, "f4").copy()
            cpu.applyRGB(out)
            return out
        return encode


def _evaluate(inputs: dict, out_type: str):
    transform = TRANSFORMS.get(inputs.get("transform"))
    if transform is None:
        raise evaluate.NotFoldable
    return transform.apply(tuple(inputs["in"]))


evaluate.REGISTERED["ocio_transform"] = _evaluate
