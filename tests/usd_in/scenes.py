"""USD test scenes written with usd-core, each beside the MaterialX document it is equivalent to."""
import os
from pathlib import Path

import numpy as np

from pxr import Gf, Sdf, Usd, UsdShade

TEXTURE = "checker.png"


def write_checker(folder: Path) -> Path:
    """An 8 x 8 sRGB PNG in four coloured quadrants (so a v flip or a lost transform shows)."""
    import OpenImageIO as oiio

    pixels = np.zeros((8, 8, 3), "u1")
    pixels[:4, :4], pixels[:4, 4:], pixels[4:, :4], pixels[4:, 4:] = [230, 40, 20], [30, 200, 60], [20, 60, 220], [250, 250, 250]
    image = oiio.ImageBuf(oiio.ImageSpec(8, 8, 3, oiio.UINT8))
    image.set_pixels(oiio.ROI(0, 8, 0, 8), pixels)
    path = folder / TEXTURE
    assert image.write(str(path)), oiio.geterror()
    return path


def _shader(stage, path: str, shader_id: str) -> UsdShade.Shader:
    shader = UsdShade.Shader.Define(stage, path)
    shader.CreateIdAttr(shader_id)
    return shader


def preview_surface_stage(stage, root: str = "/World/Looks/Textured", texture: str = TEXTURE) -> None:
    """A UsdPreviewSurface with a texture read through a primvar reader and a UsdTransform2d."""
    material = UsdShade.Material.Define(stage, root)
    surface = _shader(stage, f"{root}/Surface", "UsdPreviewSurface")
    surface.CreateInput("roughness", Sdf.ValueTypeNames.Float).Set(0.35)
    surface.CreateInput("metallic", Sdf.ValueTypeNames.Float).Set(0.2)
    reader = _shader(stage, f"{root}/Reader", "UsdPrimvarReader_float2")
    reader.CreateInput("varname", Sdf.ValueTypeNames.Token).Set("st")
    transform = _shader(stage, f"{root}/Transform", "UsdTransform2d")
    transform.CreateInput("in", Sdf.ValueTypeNames.Float2).ConnectToSource(reader.ConnectableAPI(), "result")
    transform.CreateInput("scale", Sdf.ValueTypeNames.Float2).Set(Gf.Vec2f(2, 3))
    transform.CreateInput("rotation", Sdf.ValueTypeNames.Float).Set(30.0)
    texture_shader = _shader(stage, f"{root}/Texture", "UsdUVTexture")
    texture_shader.CreateInput("file", Sdf.ValueTypeNames.Asset).Set(texture)
    texture_shader.CreateInput("sourceColorSpace", Sdf.ValueTypeNames.Token).Set("sRGB")
    texture_shader.CreateInput("st", Sdf.ValueTypeNames.Float2).ConnectToSource(transform.ConnectableAPI(), "result")
    surface.CreateInput("diffuseColor", Sdf.ValueTypeNames.Color3f).ConnectToSource(texture_shader.ConnectableAPI(),
                                                                                    "rgb")
    surface.CreateInput("clearcoat", Sdf.ValueTypeNames.Float).ConnectToSource(texture_shader.ConnectableAPI(), "r")
    material.CreateSurfaceOutput().ConnectToSource(surface.ConnectableAPI(), "surface")


PREVIEW_SURFACE_MTLX = f"""<?xml version="1.0"?>
<materialx version="1.39" colorspace="lin_rec709">
  <texcoord name="uv" type="vector2" />
  <UsdTransform2d name="transform" type="vector2">
    <input name="in" type="vector2" nodename="uv" />
    <input name="scale" type="vector2" value="2, 3" />
    <input name="rotation" type="float" value="30" />
  </UsdTransform2d>
  <UsdUVTexture name="texture" type="multioutput">
    <input name="file" type="filename" value="{TEXTURE}" colorspace="srgb_texture" />
    <input name="st" type="vector2" nodename="transform" />
  </UsdUVTexture>
  <UsdPreviewSurface name="surface" type="surfaceshader">
    <input name="diffuseColor" type="color3" nodename="texture" output="rgb" />
    <input name="clearcoat" type="float" nodename="texture" output="r" />
    <input name="roughness" type="float" value="0.35" />
    <input name="metallic" type="float" value="0.2" />
  </UsdPreviewSurface>
  <surfacematerial name="Textured" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="surface" />
  </surfacematerial>
</materialx>
"""


def standard_surface_stage(stage, root: str = "/World/Looks/Brick") -> None:
    """A MaterialX network in USD: standard_surface fed by an image inside a NodeGraph prim, and
    a value through the material's interface, on the `outputs:mtlx:surface` render context (the
    universal `outputs:surface` holds a plain UsdPreviewSurface that must be passed over)."""
    material = UsdShade.Material.Define(stage, root)
    interface = material.CreateInput("roughness", Sdf.ValueTypeNames.Float)
    interface.Set(0.6)
    graph = UsdShade.NodeGraph.Define(stage, f"{root}/Textures")
    image = _shader(stage, f"{root}/Textures/Image", "ND_image_color3")
    file = image.CreateInput("file", Sdf.ValueTypeNames.Asset)
    file.Set(TEXTURE)
    file.GetAttr().SetColorSpace("srgb_texture")
    image.CreateInput("uaddressmode", Sdf.ValueTypeNames.String).Set("mirror")
    image.CreateInput("filtertype", Sdf.ValueTypeNames.String).Set("closest")  # sampler state, set by the renderer
    uv = _shader(stage, f"{root}/Textures/UV", "ND_texcoord_vector2")
    tiled = _shader(stage, f"{root}/Textures/Tiled", "ND_multiply_vector2FA")
    tiled.CreateInput("in1", Sdf.ValueTypeNames.Float2).ConnectToSource(uv.ConnectableAPI(), "out")
    tiled.CreateInput("in2", Sdf.ValueTypeNames.Float).Set(2.5)  # so the address mode shows past u = 1
    image.CreateInput("texcoord", Sdf.ValueTypeNames.Float2).ConnectToSource(tiled.ConnectableAPI(), "out")
    image.CreateOutput("out", Sdf.ValueTypeNames.Color3f)
    graph.CreateOutput("base_color", Sdf.ValueTypeNames.Color3f).ConnectToSource(image.ConnectableAPI(), "out")
    surface = _shader(stage, f"{root}/Surface", "ND_standard_surface_surfaceshader")
    surface.CreateInput("base", Sdf.ValueTypeNames.Float).Set(0.9)
    surface.CreateInput("base_color", Sdf.ValueTypeNames.Color3f).ConnectToSource(graph.ConnectableAPI(), "base_color")
    surface.CreateInput("specular_roughness", Sdf.ValueTypeNames.Float).ConnectToSource(interface)
    surface.CreateInput("coat", Sdf.ValueTypeNames.Float).Set(0.3)
    surface.CreateInput("coat_color", Sdf.ValueTypeNames.Color3f).Set(Gf.Vec3f(0.9, 0.8, 0.5))
    surface.CreateOutput("out", Sdf.ValueTypeNames.Token)
    material.CreateSurfaceOutput("mtlx").ConnectToSource(surface.ConnectableAPI(), "out")
    fallback = _shader(stage, f"{root}/Fallback", "UsdPreviewSurface")
    material.CreateSurfaceOutput().ConnectToSource(fallback.ConnectableAPI(), "surface")


STANDARD_SURFACE_MTLX = f"""<?xml version="1.0"?>
<materialx version="1.39" colorspace="lin_rec709">
  <texcoord name="uv" type="vector2" />
  <multiply name="tiled" type="vector2">
    <input name="in1" type="vector2" nodename="uv" />
    <input name="in2" type="float" value="2.5" />
  </multiply>
  <image name="image" type="color3">
    <input name="file" type="filename" value="{TEXTURE}" colorspace="srgb_texture" />
    <input name="uaddressmode" type="string" value="mirror" />
    <input name="filtertype" type="string" value="closest" />
    <input name="texcoord" type="vector2" nodename="tiled" />
  </image>
  <standard_surface name="surface" type="surfaceshader">
    <input name="base" type="float" value="0.9" />
    <input name="base_color" type="color3" nodename="image" />
    <input name="specular_roughness" type="float" value="0.6" />
    <input name="coat" type="float" value="0.3" />
    <input name="coat_color" type="color3" value="0.9, 0.8, 0.5" />
  </standard_surface>
  <surfacematerial name="Brick" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="surface" />
  </surfacematerial>
</materialx>
"""


def write_scene(folder: Path, name: str, build) -> Path:
    """A new stage at folder/name, filled by build(stage) and saved."""
    path = folder / name
    stage = Usd.Stage.CreateNew(str(path))
    build(stage)
    stage.GetRootLayer().Save()
    return path


def write_usdz(folder: Path, name: str, layer: Path, *members: Path) -> Path:
    """A usdz package of `layer` (its first, root layer) and `members`, named relative to layer's folder."""
    path = folder / name
    writer = Sdf.ZipFileWriter.CreateNew(str(path))
    for member in (layer, *members):
        writer.AddFile(str(member), os.path.relpath(member, layer.parent))
    writer.Save()
    return path


def write_mtlx(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.write_text(text)
    return path


# -- connections across roles, and opacity (issue 21) -------------------------------------------
NORMAL_MAP = "normal.exr"
TILTED_NORMAL = (0.6, 0.0, 0.8)  # a tangent-space normal leaning towards +u
DISPLAY_COLOR_FALLBACK = (0.8, 0.3, 0.1)  # what the primvar reader gives on a mesh without displayColor


def write_normal_map(folder: Path, normal=TILTED_NORMAL) -> Path:
    """A 4 x 4 float EXR of one tangent-space normal encoded as (n + 1) / 2, exact in float."""
    import OpenImageIO as oiio

    pixels = np.empty((4, 4, 3), "f4")
    pixels[...] = (np.float32(normal) + 1) / 2
    image = oiio.ImageBuf(oiio.ImageSpec(4, 4, 3, oiio.FLOAT))
    image.set_pixels(oiio.ROI(0, 4, 0, 4), pixels)
    path = folder / NORMAL_MAP
    assert image.write(str(path)), oiio.geterror()
    return path


def role_connections_stage(stage, root: str = "/World/Looks/Roles") -> None:
    """Connections USD makes across roles of one underlying type, as sample scenes write them:
    a texture's float3 `rgb` into the surface's normal3f `normal` (a normal map decoded by scale
    and bias) and a float3 primvar reader of displayColor into the color3f `diffuseColor`."""
    material = UsdShade.Material.Define(stage, root)
    surface = _shader(stage, f"{root}/Surface", "UsdPreviewSurface")
    surface.CreateInput("roughness", Sdf.ValueTypeNames.Float).Set(0.3)
    texture = _shader(stage, f"{root}/NormalMap", "UsdUVTexture")
    texture.CreateInput("file", Sdf.ValueTypeNames.Asset).Set(NORMAL_MAP)
    texture.CreateInput("sourceColorSpace", Sdf.ValueTypeNames.Token).Set("raw")
    texture.CreateInput("scale", Sdf.ValueTypeNames.Float4).Set(Gf.Vec4f(2, 2, 2, 1))
    texture.CreateInput("bias", Sdf.ValueTypeNames.Float4).Set(Gf.Vec4f(-1, -1, -1, 0))
    rgb = texture.CreateOutput("rgb", Sdf.ValueTypeNames.Float3)
    surface.CreateInput("normal", Sdf.ValueTypeNames.Normal3f).ConnectToSource(rgb)
    reader = _shader(stage, f"{root}/DisplayColor", "UsdPrimvarReader_float3")
    reader.CreateInput("varname", Sdf.ValueTypeNames.Token).Set("displayColor")
    reader.CreateInput("fallback", Sdf.ValueTypeNames.Float3).Set(Gf.Vec3f(*DISPLAY_COLOR_FALLBACK))
    result = reader.CreateOutput("result", Sdf.ValueTypeNames.Float3)
    surface.CreateInput("diffuseColor", Sdf.ValueTypeNames.Color3f).ConnectToSource(result)
    material.CreateSurfaceOutput().ConnectToSource(surface.ConnectableAPI(), "surface")


# The same material in MaterialX on a mesh without displayColor (the sphere): the reader's fallback
# as the diffuse colour, and the normal map's normal as a value.
ROLE_CONNECTIONS_MTLX = """<?xml version="1.0"?>
<materialx version="1.39" colorspace="lin_rec709">
  <UsdPreviewSurface name="surface" type="surfaceshader">
    <input name="diffuseColor" type="color3" value="{diffuse}" />
    <input name="roughness" type="float" value="0.3" />
    <input name="normal" type="vector3" value="{normal}" />
  </UsdPreviewSurface>
  <surfacematerial name="Roles" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="surface" />
  </surfacematerial>
</materialx>
"""


def opacity_stage(stage, opacity: float = 1.0, threshold: float | None = None, mode: str | None = None,
                  texture: str | None = None, root: str = "/World/Looks/Glass") -> None:
    """A red UsdPreviewSurface of `opacity` (or, with `texture`, the red channel of that image
    read raw), with opacityThreshold and opacityMode where given."""
    material = UsdShade.Material.Define(stage, root)
    surface = _shader(stage, f"{root}/Surface", "UsdPreviewSurface")
    surface.CreateInput("diffuseColor", Sdf.ValueTypeNames.Color3f).Set(Gf.Vec3f(0.8, 0.1, 0.1))
    surface.CreateInput("roughness", Sdf.ValueTypeNames.Float).Set(0.1)
    opacity_input = surface.CreateInput("opacity", Sdf.ValueTypeNames.Float)
    if texture:
        image = _shader(stage, f"{root}/Opacity", "UsdUVTexture")
        image.CreateInput("file", Sdf.ValueTypeNames.Asset).Set(texture)
        image.CreateInput("sourceColorSpace", Sdf.ValueTypeNames.Token).Set("raw")
        opacity_input.ConnectToSource(image.CreateOutput("r", Sdf.ValueTypeNames.Float))
    else:
        opacity_input.Set(opacity)
    if threshold is not None:
        surface.CreateInput("opacityThreshold", Sdf.ValueTypeNames.Float).Set(threshold)
    if mode is not None:
        surface.CreateInput("opacityMode", Sdf.ValueTypeNames.Token).Set(mode)
    material.CreateSurfaceOutput().ConnectToSource(surface.ConnectableAPI(), "surface")
