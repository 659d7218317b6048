"""The fixed scene every thumbnail is drawn in: the camera, the object transform, time and frame.

The conventions are the reference renderer's (../shared/oracle/mx_refrender.py) so that images of
the two compare pixel for pixel: object at the origin with an identity world matrix, eye at
(0, 0, 3) looking at the origin with +Y up, vertical field of view 45 degrees, near 0.05, far 100,
square image. Matrices are numpy arrays acting on column vectors (p' = M @ p); GLSL stores them
column-major, which `matrix_bytes` takes care of.
"""
import numpy as np

EYE = np.array([0.0, 0.0, 3.0])
TARGET = np.zeros(3)
UP = np.array([0.0, 1.0, 0.0])
FOV_Y_DEGREES = 45.0
NEAR, FAR = 0.05, 100.0
# A thumbnail is a still: animated graphs (time, frame nodes) are drawn at this instant.
TIME_SECONDS, FRAME = 0.0, 1.0


def look_at(eye: np.ndarray, target: np.ndarray, up: np.ndarray) -> np.ndarray:
    forward = (target - eye) / np.linalg.norm(target - eye)
    side = np.cross(forward, up)
    side /= np.linalg.norm(side)
    true_up = np.cross(side, forward)
    view = np.eye(4)
    view[0, :3], view[1, :3], view[2, :3] = side, true_up, -forward
    view[:3, 3] = -view[:3, :3] @ eye
    return view


def perspective(fov_y_degrees: float, aspect: float, near: float, far: float) -> np.ndarray:
    f = 1.0 / np.tan(np.radians(fov_y_degrees) / 2.0)
    proj = np.zeros((4, 4))
    proj[0, 0], proj[1, 1] = f / aspect, f
    proj[2, 2], proj[2, 3] = (far + near) / (near - far), 2.0 * far * near / (near - far)
    proj[3, 2] = -1.0
    return proj


def matrix_bytes(m: np.ndarray) -> bytes:
    """A column-vector numpy matrix as the bytes of a GLSL matN uniform (column-major)."""
    return np.asarray(m, "f4").T.tobytes()


# GL's clip space has z in -w..w, WebGPU's (Vulkan's, D3D's) 0..w: z' = (z + w) / 2.
DEPTH_ZERO_TO_ONE = np.array([[1.0, 0, 0, 0], [0, 1.0, 0, 0], [0, 0, 0.5, 0.5], [0, 0, 0, 1.0]])


def scene_uniforms(depth_zero_to_one: bool = False) -> dict[str, object]:
    """Every predefined scene uniform of the seed's figure 7, by name: matrices as numpy 4x4
    arrays, vectors as tuples, time and frame as floats. `depth_zero_to_one`: the projection
    maps depth into WebGPU's clip space (the same image: x and y are untouched)."""
    world = np.eye(4)
    view = look_at(EYE, TARGET, UP)
    proj = perspective(FOV_Y_DEGREES, 1.0, NEAR, FAR)
    if depth_zero_to_one:
        proj = DEPTH_ZERO_TO_ONE @ proj
    matrices = {"world": world, "view": view, "projection": proj,
                "worldView": view @ world, "viewProjection": proj @ view,
                "worldViewProjection": proj @ view @ world}
    uniforms: dict[str, object] = {}
    for name, m in matrices.items():
        uniforms[f"u_{name}Matrix"] = m
        if name in ("world", "view", "projection"):  # the seed defines the variants for these three
            inverse = np.linalg.inv(m)
            uniforms[f"u_{name}InverseMatrix"] = inverse
            uniforms[f"u_{name}TransposeMatrix"] = m.T
            uniforms[f"u_{name}InverseTransposeMatrix"] = inverse.T
    forward = (TARGET - EYE) / np.linalg.norm(TARGET - EYE)
    uniforms["u_viewPosition"] = tuple(EYE)
    uniforms["u_viewDirection"] = tuple(forward)
    uniforms["u_time"] = TIME_SECONDS
    uniforms["u_frame"] = FRAME
    return uniforms
