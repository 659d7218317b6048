"""Meshes to draw a material on: UV sphere, plane, Wavefront OBJ, with every vertex stream a
MaterialX shader may declare (the seed's app-data names: i_position, i_normal, i_tangent,
i_bitangent, i_texcoord_N, i_color_N, i_geomprop_NAME)."""
import math
import os
import re
from dataclasses import dataclass

import numpy as np

from .errors import RenderError


@dataclass
class Mesh:
    name: str
    streams: dict[str, np.ndarray]  # stream name -> float32 (vertex count, components)
    indices: np.ndarray             # uint32 triangle list

    def stream(self, name: str, components: int) -> np.ndarray:
        """The float32 data for vertex input `name` with `components` columns. Streams a mesh
        cannot lack get MaterialX's defaults: white vertex colours, zero geometric properties,
        the first uv set for further sets, a bitangent from normal and tangent. A stream with no
        sensible default (positions, normals, texture coordinates, tangents) raises
        missing_stream."""
        data = self.streams.get(name)
        if data is None:
            data = self._default_stream(name, components)
        return _fit_columns(data, components, fill=1.0 if name.startswith("i_color_") else 0.0)

    def _default_stream(self, name: str, components: int) -> np.ndarray:
        count = len(self.streams["i_position"])
        if name.startswith("i_color_"):
            return np.ones((count, 4), "f4")
        if name.startswith("i_geomprop_"):
            return np.zeros((count, components), "f4")
        if re.fullmatch(r"i_texcoord_\d+", name) and "i_texcoord_0" in self.streams:
            return self.streams["i_texcoord_0"]
        if name == "i_bitangent" and {"i_normal", "i_tangent"} <= self.streams.keys():
            return np.cross(self.streams["i_normal"], self.streams["i_tangent"]).astype("f4")
        have = ", ".join(sorted(self.streams))
        raise RenderError("missing_stream", f"the shader reads vertex stream {name}, which mesh "
                          f"{self.name!r} does not have (it has {have})", name)


def primvar_defaults(mesh: Mesh, record: dict) -> dict[str, list]:
    """Stream name -> value of each primvar the record reads and the mesh lacks that the record's
    listing gives a value: a geompropvalue's `default`, what MaterialX returns where the geometry
    does not define the property (a UsdPrimvarReader's fallback). Those without one stay zero."""
    defaults = {}
    for v in record.get("blocks", {}).get("vertex", {}).get("AppData", []):
        name, value = (v.get("name"), v.get("value")) if isinstance(v, dict) else (None, None)
        if not (isinstance(name, str) and name.startswith("i_geomprop_")) or value is None or name in mesh.streams:
            continue
        numbers = value if isinstance(value, list) else [value]
        if not 1 <= len(numbers) <= 4 or not all(isinstance(x, (int, float)) and math.isfinite(x) for x in numbers):
            raise RenderError("invalid_record", f"AppData {name}: value must be 1 to 4 finite numbers", name)
        defaults[name] = [float(x) for x in numbers]
    return defaults


def with_constant_streams(mesh: Mesh, values: dict[str, list]) -> Mesh:
    """The mesh with a stream of one value at every vertex for each of `values`."""
    count = len(mesh.streams["i_position"])
    constant = {name: np.tile(np.float32(value), (count, 1)) for name, value in values.items()}
    return Mesh(mesh.name, {**mesh.streams, **constant}, mesh.indices)


def _fit_columns(data: np.ndarray, components: int, fill: float) -> np.ndarray:
    """Truncate or pad (with `fill`) to the width the shader declares, e.g. a vec3 texcoord."""
    have = data.shape[1]
    if have >= components:
        return np.ascontiguousarray(data[:, :components], "f4")
    pad = np.full((len(data), components - have), fill, "f4")
    return np.ascontiguousarray(np.concatenate([data, pad], 1), "f4")


def uv_sphere(columns: int = 128, rows: int = 64) -> Mesh:
    """Unit sphere; u runs with longitude from +Z towards +X, v from the south pole (0) to the north
    pole (1); the tangent is dP/du and the bitangent N x T (= dP/dv direction). The reference
    renderer tessellates the same way, so silhouettes and interpolated attributes match."""
    lon = np.linspace(0.0, 2.0 * np.pi, columns + 1)
    lat = np.linspace(-0.5 * np.pi, 0.5 * np.pi, rows + 1)
    lon, lat = np.meshgrid(lon, lat)  # row j: latitude j, bottom to top
    normal = np.stack([np.cos(lat) * np.sin(lon), np.sin(lat), np.cos(lat) * np.cos(lon)], -1).reshape(-1, 3)
    tangent = np.stack([np.cos(lon), np.zeros_like(lon), -np.sin(lon)], -1).reshape(-1, 3)
    uv = np.stack([lon / (2.0 * np.pi), lat / np.pi + 0.5], -1).reshape(-1, 2)
    quad = np.arange(rows)[:, None] * (columns + 1) + np.arange(columns)[None, :]
    a, b = quad.ravel(), quad.ravel() + 1
    c, d = a + columns + 1, b + columns + 1
    indices = np.stack([a, b, d, a, d, c], -1).ravel()
    return _mesh("sphere", normal, normal, uv, tangent, indices)


def plane() -> Mesh:
    """A 2 x 2 square in the z = 0 plane facing the camera (+Z), uv (0,0) at the bottom left."""
    position = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], "f4")
    normal = np.tile(np.array([0, 0, 1], "f4"), (4, 1))
    tangent = np.tile(np.array([1, 0, 0], "f4"), (4, 1))
    uv = (position[:, :2] + 1.0) / 2.0
    return _mesh("plane", position, normal, uv, tangent, np.array([0, 1, 2, 0, 2, 3]))


def _mesh(name, position, normal, uv, tangent, indices) -> Mesh:
    streams = {"i_position": position, "i_normal": normal, "i_texcoord_0": uv, "i_tangent": tangent}
    streams = {k: np.ascontiguousarray(v, "f4") for k, v in streams.items()}
    streams["i_bitangent"] = np.cross(streams["i_normal"], streams["i_tangent"]).astype("f4")
    return Mesh(name, streams, np.asarray(indices, "u4"))


def load_obj(path: str) -> Mesh:
    """A Wavefront OBJ (v, vt, vn, polygonal f; other statements ignored), centred and scaled to
    fit the unit sphere so that the fixed camera frames it. Missing normals are computed (area
    weighted); tangents are derived from the first uv set when there is one."""
    positions, uvs, normals, corners = [], [], [], []
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                fields = line.split()
                if not fields:
                    continue
                tag, args = fields[0], fields[1:]
                if tag == "v":
                    positions.append([float(x) for x in args[:3]])
                elif tag == "vt":
                    uvs.append([float(x) for x in (args + ["0"])[:2]])
                elif tag == "vn":
                    normals.append([float(x) for x in args[:3]])
                elif tag == "f":
                    polygon = [_obj_corner(c, len(positions), len(uvs), len(normals)) for c in args]
                    corners += [c for i in range(1, len(polygon) - 1)
                                for c in (polygon[0], polygon[i], polygon[i + 1])]
    except OSError as exc:
        raise RenderError("invalid_mesh", f"cannot read {path}: {exc.strerror}", path) from exc
    except (ValueError, IndexError) as exc:
        raise RenderError("invalid_mesh", f"malformed OBJ statement: {exc}", f"{path}:{number}") from exc
    if not corners:
        raise RenderError("invalid_mesh", "the OBJ file has no faces", path)
    # One vertex per distinct (position, uv, normal) triple, as GL needs.
    unique, indices = np.unique(np.array(corners, "i8"), axis=0, return_inverse=True)
    position = np.array(positions, "f8")[unique[:, 0]]
    centre = (position.min(0) + position.max(0)) / 2.0
    radius = np.linalg.norm(position - centre, axis=1).max() or 1.0
    position = (position - centre) / radius
    indices = indices.ravel()
    has_uv = bool(uvs) and bool((unique[:, 1] >= 0).all())
    has_normal = bool(normals) and bool((unique[:, 2] >= 0).all())
    normal = _unit(np.array(normals, "f8")[unique[:, 2]]) if has_normal else _vertex_normals(position, indices)
    streams = {"i_position": position, "i_normal": normal}
    if has_uv:
        uv = np.array(uvs, "f8")[unique[:, 1]]
        tangent = _uv_tangents(position, normal, uv, indices)
        streams.update(i_texcoord_0=uv, i_tangent=tangent, i_bitangent=np.cross(normal, tangent))
    name = os.path.basename(path)
    return Mesh(name, {k: np.ascontiguousarray(v, "f4") for k, v in streams.items()}, indices.astype("u4"))


def _obj_corner(text: str, n_pos: int, n_uv: int, n_normal: int) -> tuple[int, int, int]:
    """'v', 'v/vt', 'v//vn' or 'v/vt/vn' (1-based, negative counts from the end) -> 0-based, -1 absent."""
    parts = (text.split("/") + ["", ""])[:3]

    def index(s: str, count: int) -> int:
        if not s:
            return -1
        i = int(s)
        resolved = i - 1 if i > 0 else count + i
        if not 0 <= resolved < count:
            raise IndexError(f"index {i} out of range")
        return resolved

    return index(parts[0], n_pos), index(parts[1], n_uv), index(parts[2], n_normal)


def _unit(v: np.ndarray) -> np.ndarray:
    length = np.linalg.norm(v, axis=-1, keepdims=True)
    return v / np.where(length > 0, length, 1.0)


def _vertex_normals(position: np.ndarray, indices: np.ndarray) -> np.ndarray:
    """Smooth normals: area-weighted face normals summed over vertices that share a position."""
    tri = indices.reshape(-1, 3)
    face = np.cross(position[tri[:, 1]] - position[tri[:, 0]], position[tri[:, 2]] - position[tri[:, 0]])
    _, shared = np.unique(position, axis=0, return_inverse=True)
    shared = shared.ravel()
    summed = np.zeros((shared.max() + 1, 3))
    for k in range(3):
        np.add.at(summed, shared[tri[:, k]], face)
    return _unit(summed[shared])


def _uv_tangents(position, normal, uv, indices) -> np.ndarray:
    """Per-vertex dP/du from the triangles' uv gradients, made orthogonal to the normal."""
    tri = indices.reshape(-1, 3)
    e1, e2 = position[tri[:, 1]] - position[tri[:, 0]], position[tri[:, 2]] - position[tri[:, 0]]
    d1, d2 = uv[tri[:, 1]] - uv[tri[:, 0]], uv[tri[:, 2]] - uv[tri[:, 0]]
    det = d1[:, 0] * d2[:, 1] - d2[:, 0] * d1[:, 1]
    face = (e1 * d2[:, 1:2] - e2 * d1[:, 1:2]) / np.where(np.abs(det) > 1e-20, det, 1.0)[:, None]
    summed = np.zeros_like(position)
    for k in range(3):
        np.add.at(summed, tri[:, k], face)
    tangent = summed - normal * np.sum(summed * normal, -1, keepdims=True)
    # Where the uv mapping is degenerate, any direction orthogonal to the normal will do.
    fallback = np.cross(normal, np.where(np.abs(normal[:, :1]) < 0.9, [[1.0, 0, 0]], [[0, 1.0, 0]]))
    degenerate = np.linalg.norm(tangent, axis=1) < 1e-12
    tangent[degenerate] = fallback[degenerate]
    return _unit(tangent)


def load_mesh(spec: str) -> Mesh:
    """'sphere', 'plane' or the path of an .obj file."""
    if spec == "sphere":
        return uv_sphere()
    if spec == "plane":
        return plane()
    if spec.lower().endswith(".obj"):
        return load_obj(spec)
    raise RenderError("invalid_mesh", f"unknown mesh {spec!r}: use sphere, plane or a .obj file", spec)
