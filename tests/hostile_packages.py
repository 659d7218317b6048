"""Files that are small to send but large, lying or unreadable, once read: usdz packages and images
built with zipfile, struct and OpenImageIO, for the tests of the archive and image bounds (renderer and live service).

    textured_layer(texture)             a usda layer of one material drawing a texture
    usdz(members, compressed=())        a zip of (name, bytes) members, stored unless named in `compressed`
    deflate_bomb_package(texture, n)    that layer, and its texture n zero bytes deflated (about n / 1000 sent)
    with_directory_size(package, ...)   the package with a member's size in its directory (and local header) changed
    png(width, height, rgb)             a real PNG of one colour
    huge_png_header(w, h)               a PNG of a few hundred bytes whose header declares w x h pixels
    deep_exr()                          a deep OpenEXR, which OpenImageIO's Python binding cannot read safely
"""
import io
import struct
import zipfile
import zlib

import numpy as np

LAYER = "scene.usda"


def textured_layer(texture: str) -> str:
    """A usda layer of one UsdPreviewSurface material whose diffuseColor is the texture's rgb."""
    return f'''#usda 1.0
def Scope "Looks"
{{
    def Material "Wood"
    {{
        token outputs:surface.connect = </Looks/Wood/Surface.outputs:surface>
        def Shader "Surface"
        {{
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:diffuseColor.connect = </Looks/Wood/Texture.outputs:rgb>
            float inputs:roughness = 0.5
            token outputs:surface
        }}
        def Shader "Texture"
        {{
            uniform token info:id = "UsdUVTexture"
            asset inputs:file = @{texture}@
            float3 outputs:rgb
        }}
    }}
}}
'''


def usdz(members: list[tuple[str, bytes]], compressed: tuple[str, ...] = ()) -> bytes:
    """A zip of the members in order, each stored unless its name is in `compressed`; a member given
    as (name, int) is that many zero bytes, written in pieces (a bomb is never held whole)."""
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w") as archive:
        for name, data in members:
            method = zipfile.ZIP_DEFLATED if name in compressed else zipfile.ZIP_STORED
            info = zipfile.ZipInfo(name, (2024, 1, 1, 0, 0, 0))
            info.compress_type = method
            with archive.open(info, "w") as member:
                if isinstance(data, int):
                    piece = bytes(1 << 20)
                    for _ in range(data >> 20):
                        member.write(piece)
                else:
                    member.write(data)
    return out.getvalue()


def deflate_bomb_package(texture: str, size: int) -> bytes:
    """A package whose layer is stored and whose texture member is `size` zero bytes deflated."""
    return usdz([(LAYER, textured_layer(texture).encode()), (texture, size)], compressed=(texture,))


def with_directory_size(package: bytes, member: str, size: int, local_header_too: bool = False) -> bytes:
    """The package with `member`'s sizes (compressed and uncompressed) in the central directory,
    and in its local header when `local_header_too`, replaced by `size`: the data stays as it is."""
    data = bytearray(package)
    with zipfile.ZipFile(io.BytesIO(package)) as archive:
        info = archive.getinfo(member)
        entry = archive.start_dir
    name = member.encode()
    while data[entry + 46:entry + 46 + len(name)] != name:  # walk the directory to the member's entry
        name_length, extra_length, comment_length = struct.unpack_from("<HHH", data, entry + 28)
        entry += 46 + name_length + extra_length + comment_length
    struct.pack_into("<LL", data, entry + 20, size, size)
    if local_header_too:
        struct.pack_into("<LL", data, info.header_offset + 18, size, size)
    return bytes(data)


def png(width: int, height: int, rgb: tuple[int, int, int]) -> bytes:
    """A real PNG (8-bit RGB) of one colour."""
    raw = np.zeros((height, width * 3 + 1), "u1")
    raw[:, 1:] = np.tile(np.array(rgb, "u1"), width)
    return _png(width, height, zlib.compress(raw.tobytes()))


def huge_png_header(width: int, height: int) -> bytes:
    """A PNG whose header declares width x height RGB pixels and whose data is a few bytes: any
    reader that decodes before looking at the header allocates width x height x 3 bytes or more."""
    return _png(width, height, zlib.compress(bytes(64)))


def deep_exr() -> bytes:
    """A 4 x 4 deep OpenEXR (three samples a pixel), written by OpenImageIO."""
    import os
    import tempfile

    import OpenImageIO as oiio

    spec = oiio.ImageSpec(4, 4, 2, oiio.FLOAT)
    spec.deep, spec.channelnames = True, ("A", "Z")
    deep = oiio.DeepData()
    deep.init(spec)
    for pixel in range(16):
        deep.set_samples(pixel, 3)
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "deep.exr")
        out = oiio.ImageOutput.create(path)
        assert out.open(path, spec) and out.write_deep_image(deep), out.geterror()
        out.close()
        return open(path, "rb").read()


def _png(width: int, height: int, idat: bytes) -> bytes:
    def chunk(kind: bytes, body: bytes) -> bytes:
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", idat) + chunk(b"IEND", b"")


def nested_references(depth: int, fan_out: int = 2) -> str:
    """A layer of `depth` prims, each with `fan_out` children referencing the prim before it: a
    few kilobytes that compose to about fan_out ** depth prims."""
    prims = ['def "L0"\n{\n    def "leaf"\n    {\n    }\n}']
    for level in range(1, depth + 1):
        children = "".join(f'    def "c{c}" (\n        references = </L{level - 1}>\n    )\n    {{\n    }}\n'
                           for c in range(fan_out))
        prims.append(f'def "L{level}"\n{{\n{children}}}')
    return "#usda 1.0\n" + "\n".join(prims) + "\n"

