"""Every file texture is stored in one format (RGBA float32, no swizzle), whatever its channels:
llvmpipe compiles a program's machine code per texture format and swizzle bound, so a library of
one topology whose files have different channel counts would otherwise compile it again and again.
What the shader reads is unchanged: grey as grey, grey-alpha as grey with its alpha, RGB opaque."""
import numpy as np
import pytest

from shadergen.render.context import gl_context
from shadergen.render.textures import upload

H, W = 4, 8


def image(channels: int) -> np.ndarray:
    rng = np.random.default_rng(channels)
    return rng.random((H, W, channels), dtype=np.float32)


@pytest.mark.parametrize("channels, expected", [
    (1, lambda i: np.concatenate([i, i, i, np.ones_like(i)], axis=2)),
    (2, lambda i: np.concatenate([i[..., :1]] * 3 + [i[..., 1:2]], axis=2)),
    (3, lambda i: np.concatenate([i, np.ones_like(i[..., :1])], axis=2)),
    (4, lambda i: i),
])
def test_a_file_texture_of_any_channel_count_is_rgba_and_reads_as_before(channels, expected):
    ctx = gl_context()
    source = image(channels)
    texture = upload(ctx, source)
    try:
        assert (texture.components, texture.dtype, texture.swizzle) == (4, "f4", "RGBA")
        stored = np.frombuffer(texture.read(), "f4").reshape(H, W, 4)
        np.testing.assert_array_equal(stored, expected(source))
    finally:
        texture.release()
