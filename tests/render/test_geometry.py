"""Meshes and their vertex streams (no GL needed)."""
import numpy as np
import pytest

from shadergen.render import RenderError
from shadergen.render.geometry import load_obj, plane, uv_sphere

from .conftest import DATA


def test_sphere_streams_follow_the_reference_conventions():
    mesh = uv_sphere()
    p, n, t, b, uv = (mesh.streams[k] for k in ("i_position", "i_normal", "i_tangent", "i_bitangent", "i_texcoord_0"))
    np.testing.assert_allclose(np.linalg.norm(p, axis=1), 1, atol=1e-6)
    np.testing.assert_allclose(p, n, atol=1e-7)
    np.testing.assert_allclose(np.sum(n * t, 1), 0, atol=1e-6)
    # u grows towards +X from +Z (tangent), v towards the north pole (bitangent)
    front = np.argmin(np.linalg.norm(p - [0, 0, 1], axis=1))
    np.testing.assert_allclose(t[front], [1, 0, 0], atol=1e-6)
    np.testing.assert_allclose(b[front], [0, 1, 0], atol=1e-6)
    assert uv[front, 1] == pytest.approx(0.5)
    assert mesh.indices.max() < len(p) and len(mesh.indices) == 128 * 64 * 6


def test_default_streams_and_declared_widths():
    mesh = plane()
    assert mesh.stream("i_color_0", 4).tolist() == [[1.0] * 4] * 4
    assert mesh.stream("i_color_1", 3).shape == (4, 3)
    assert not mesh.stream("i_geomprop_age", 1).any()
    np.testing.assert_array_equal(mesh.stream("i_texcoord_2", 2), mesh.streams["i_texcoord_0"])
    texcoord3 = mesh.stream("i_texcoord_0", 3)  # a vec3 texcoord: padded with 0
    assert texcoord3.shape == (4, 3) and not texcoord3[:, 2].any()


def test_obj_without_normals_gets_them_with_tangents_from_uvs():
    mesh = load_obj(str(DATA / "quad.obj"))
    assert len(mesh.streams["i_position"]) == 4 and len(mesh.indices) == 6
    np.testing.assert_allclose(mesh.streams["i_normal"], [[0, 0, 1]] * 4, atol=1e-6)
    np.testing.assert_allclose(mesh.streams["i_tangent"], [[1, 0, 0]] * 4, atol=1e-6)
    assert np.linalg.norm(mesh.streams["i_position"], axis=1).max() == pytest.approx(1.0)  # fits the unit sphere


def test_obj_missing_streams_and_bad_files_fail_clearly(tmp_path):
    mesh = load_obj(str(DATA / "triangle_no_uv.obj"))
    with pytest.raises(RenderError) as caught:
        mesh.stream("i_tangent", 3)
    assert caught.value.code == "missing_stream"
    (tmp_path / "bad.obj").write_text("v 0 0 0\nf 1 2 3\n")
    with pytest.raises(RenderError) as caught:
        load_obj(str(tmp_path / "bad.obj"))
    assert caught.value.code == "invalid_mesh" and caught.value.where.endswith("bad.obj:2")
