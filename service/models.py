"""Request and response models: the single source of the HTTP schema (openapi.yaml is generated
from them). Records come from the generator; their models describe the contract's fields and
let the generator add more."""
from typing import Annotated, Any, Literal

from pydantic import AfterValidator, BaseModel, ConfigDict, Field, StringConstraints

Interface = Literal["complete", "reduced", "specialized"]
Values = Literal["listing", "source"]
VALUES_DOC = ("listing: uniforms initialised to the nodedef's values, so materials that differ only in values share "
              "one source (the document's values are in the listing); source: the document's values written into "
              "the initializers too")
Names = Literal["structural", "document"]
NAMES_DOC = ("structural: the source names nodes and uniforms by the graph's structure (u_n12_base_color), so materials "
             "that differ only in their element names share one source and topology hash (bind by the listing's "
             "paths); document: by the document's element names, for clients that bind uniforms by name")
Cms = Literal["builtin", "ocio"]
CMS_DOC = ("colour management system: builtin (the library's transforms to lin_rec709) or ocio (OpenColorIO: any "
           "colour space of the config); default: ocio when ocio_config is given, else builtin")
# a request names one of OCIO's built-in configs, never a file of the server's (service/generation.py
# check_config): the contract says so, so a client's validator refuses it before the server does
OCIO_CONFIG_PATTERN = "^ocio://"
OCIO_CONFIG_DOC = ("with cms ocio: one of OCIO's built-in configs (ocio://default, "
                   "ocio://cg-config-v2.1.0_aces-v1.3_ocio-v2.3, ...); the server's own config file (its "
                   "SHADERGEN_OCIO_CONFIG) when absent. A request names no file of the server")
Mesh = Literal["sphere", "plane"]
EnvMethod = Literal["fis", "prefilter", "hybrid"]
INTERFACE_DOC = ("complete: every input a uniform; reduced: only inputs bound to an interface and textures; "
                 "specialized: values folded into the code and whatever cannot contribute removed (zero-weight "
                 "lobes, untaken branches, unused functions, uniforms and vertex data), inputs in `keep` left live")


def _encodable(value: str) -> str:
    """JSON may escape a lone surrogate (`"\\ud800"`); no such string can be UTF-8, so none is text."""
    try:
        value.encode("utf-8")
    except UnicodeEncodeError as exc:
        raise ValueError(f"unpaired surrogate at character {exc.start}") from None
    return value


Text = Annotated[str, AfterValidator(_encodable)]
Keep = Annotated[Text, StringConstraints(min_length=1, max_length=1024)]
# (the constraints before the validator: after it, pydantic leaves the pattern out of the JSON schema)
OcioConfig = Annotated[str, StringConstraints(max_length=256, pattern=OCIO_CONFIG_PATTERN), AfterValidator(_encodable)]
View = Annotated[str, StringConstraints(min_length=1, max_length=256), AfterValidator(_encodable)]
VIEW_DOC = ("with cms ocio: the view of the config's default display the PNG shows the working space through "
            "(the CG config's: 'ACES 1.0 - SDR Video', tone-mapped, its default; 'Un-tone-mapped'; 'Raw'); "
            "default: the config's default view, as `shadergen render --cms ocio`. 422 unknown_view lists the "
            "config's views")


# -- requests ----------------------------------------------------------------------------------
class GenerateRequest(BaseModel):
    model_config = ConfigDict(extra="forbid")
    document: Text = Field(min_length=1, description="the MaterialX document (XML text)")
    target: Text = Field("glsl", max_length=64, description="glsl, essl, wgsl, vulkan, hlsl, slang, msl or osl")
    element: Text | None = Field(None, max_length=1024, description="name path; default: the first renderable")
    interface: Interface = Field("complete", description=INTERFACE_DOC)
    keep: list[Keep] = Field(default_factory=list, max_length=256,
                             description="with interface specialized: document inputs (node/input) that stay live "
                                         "uniforms and keep their lobes")
    values: Values = Field("listing", description=VALUES_DOC)
    names: Names = Field("structural", description=NAMES_DOC)
    cms: Cms | None = Field(None, description=CMS_DOC)
    ocio_config: OcioConfig | None = Field(None, description=OCIO_CONFIG_DOC)
    source: bool = Field(True, description="false: listings without stage source")


class ThumbnailRequest(BaseModel):
    model_config = ConfigDict(extra="forbid")
    document: Text = Field(min_length=1, description="the MaterialX document (XML text)")
    element: Text | None = Field(None, max_length=1024)
    interface: Interface = Field("specialized", description="specialized (default) renders the same image as "
                                                            "complete from the smallest shader")
    size: int = Field(256, ge=16, le=1024, description="width and height in pixels")
    mesh: Mesh = "sphere"
    env_method: EnvMethod = Field("fis", description="environment lighting: fis (16 importance samples per pixel), "
                                  "prefilter (a GGX-prefiltered map and a DFG table: one lookup) or hybrid (that "
                                  "lookup corrected by 4 samples of the prefiltered map)")
    cms: Cms | None = Field(None, description=CMS_DOC)
    ocio_config: OcioConfig | None = Field(None, description=OCIO_CONFIG_DOC)
    view: View | None = Field(None, description=VIEW_DOC)


class BatchDocument(BaseModel):
    model_config = ConfigDict(extra="forbid")
    document: Text = Field(min_length=1, description="the MaterialX document (XML text)")
    name: Text | None = Field(None, max_length=1024, description="the client's name for it, given back in its result")
    element: Text | None = Field(None, max_length=1024, description="name path; default: the first renderable")


class ThumbnailBatchRequest(BaseModel):
    model_config = ConfigDict(extra="forbid")
    documents: list[BatchDocument] = Field(min_length=1, description="the library's documents; at most "
                                           "SHADERGEN_MAX_BATCH_DOCUMENTS (413 too_large beyond it)")
    interface: Interface = Field("complete", description="complete (default): value-free source, one compiled "
                                 "program per topology for the whole library; " + INTERFACE_DOC)
    size: int = Field(256, ge=16, le=1024, description="width and height in pixels")
    mesh: Mesh = "sphere"
    env_method: EnvMethod = "fis"
    cms: Cms | None = Field(None, description=CMS_DOC)
    ocio_config: OcioConfig | None = Field(None, description=OCIO_CONFIG_DOC)
    view: View | None = Field(None, description=VIEW_DOC)


# -- responses ---------------------------------------------------------------------------------
class ErrorDetail(BaseModel):
    code: str
    message: str
    where: str | None = None


class ErrorResponse(BaseModel):
    document: str | None = None
    element: str | None = None
    target: str | None = None
    error: ErrorDetail


UiNumber = float | list[float]  # typed like the input: a number, or an array for vectors and colours


class UiHints(BaseModel):
    """What an editor needs to draw a control, from the nodedef input; typed like the input."""
    model_config = ConfigDict(extra="allow")
    name: str | None = None
    folder: str | None = None
    min: UiNumber | None = None
    max: UiNumber | None = None
    softmin: UiNumber | None = None
    softmax: UiNumber | None = None
    step: UiNumber | None = None
    advanced: bool | None = None
    doc: str | None = None
    enum: list[str] | None = Field(None, description="the names a menu shows")
    enumvalues: list[Any] | None = Field(None, description="the value of each name, typed like the input")


class Variable(BaseModel):
    model_config = ConfigDict(extra="allow")
    name: str
    type: str
    value: Any = None
    path: str | None = None
    semantic: str | None = None
    unit: str | None = None
    colorspace: str | None = None
    ui: UiHints | None = None
    fallback: Any = Field(None, description="filename variables only: the value of the image node's `default` input, "
                                            "what it gives when the file is missing or unreadable (absent when that "
                                            "input is not a constant)")


class ShaderRecord(BaseModel):
    model_config = ConfigDict(extra="allow")
    document: str | None = None
    element: str
    target: str
    interface: Interface
    hash: str = Field(description="canonical graph hash: the cache key")
    topology_hash: str = Field(description="the graph hash without the values the listing carries: what decides "
                                           "the source")
    cached: bool
    stages: dict[str, str | None] = Field(default_factory=dict, description="source by stage; null for every "
                                          "stage of a request with source false")
    blocks: dict[str, dict[str, list[Variable]]]
    timings_ms: dict[str, float] = Field(default_factory=dict)
    warnings: list[Any] = Field(default_factory=list)
    layout: dict[str, Any] | None = Field(None, description=(
        "wgsl and vulkan: per stage, the uniform buffer (wgsl group, vulkan set; binding 0; size) with each "
        "member's byte offset by WGSL's alignment rules (vulkan: std140, the same offsets), and each texture's "
        "texture and sampler bindings"))
    spirv: dict[str, str] | None = Field(None, description="vulkan only: each stage's SPIR-V module "
                                         "(glslangValidator -V, Vulkan 1.0), base64")


class JobAccepted(BaseModel):
    id: str
    state: Literal["queued", "running", "done", "failed"]
    status_url: str


class JobStatus(BaseModel):
    id: str
    state: Literal["queued", "running", "done", "failed"]
    error: ErrorDetail | None = None
    attempts: int = Field(0, description="2 when a render worker died on the job and it was tried again")
    thumbnail_url: str | None = Field(None, description="where the PNG is, once done")
    timings_ms: dict[str, float] = Field(default_factory=dict)


class BatchResult(BaseModel):
    index: int = Field(description="the document's place in the request")
    name: str | None = None
    element: str | None = Field(None, description="the material drawn, once known")
    state: Literal["queued", "done", "failed"]
    thumbnail_url: str | None = Field(None, description="where the PNG is, once done")
    error: ErrorDetail | None = Field(None, description="why it failed: the error record of that document alone")


class BatchStatus(BaseModel):
    id: str
    state: Literal["running", "done"]
    total: int
    done: int = Field(description="results ready so far, thumbnails and errors")
    failed: int
    results: list[BatchResult] = Field(description="one per document, in the request's order")


class NodeDefPort(BaseModel):
    model_config = ConfigDict(extra="allow")
    name: str
    type: str


class NodeDef(BaseModel):
    model_config = ConfigDict(extra="allow")
    name: str
    node: str
    nodegroup: str | None = None
    inputs: list[NodeDefPort] = Field(default_factory=list)
    outputs: list[NodeDefPort] = Field(default_factory=list)


class PreviewMesh(BaseModel):
    name: str
    vertices: int
    indices: int = Field(description="uint32 triangle list length")
    streams: dict[str, int] = Field(description="vertex input name -> components (float32)")


class PreviewImage(BaseModel):
    height: int
    width: int
    channels: int = Field(description="float32 per texel, rows top first")


class PreviewScene(BaseModel):
    uniforms: dict[str, list[float]] = Field(
        description="the scene's and environment's uniforms as thumbnails bind them; matrices column-major")
    background: float = Field(description="linear grey that transparent pixels are composited over")
    mesh: PreviewMesh
    environment: dict[str, PreviewImage] = Field(description="sampler name -> lat-long map")


class Health(BaseModel):
    status: Literal["ok"]
    library_hash: str
    cache: str
    jobs: str


class ComponentReadiness(BaseModel):
    ready: bool
    detail: str


class Readiness(BaseModel):
    status: Literal["ready", "not_ready"]
    generator: ComponentReadiness = Field(description="this API worker's generator processes: all running, and "
                                          "one heard from (a heartbeat) within the readiness deadline")
    render: ComponentReadiness = Field(description="the render pool (or the Celery broker), and a render process "
                                       "heard from within the readiness deadline")
    cache: ComponentReadiness = Field(description="the shared cache answers a lookup")
