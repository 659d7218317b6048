"""The process's one headless OpenGL context (moderngl on EGL; Mesa llvmpipe when there is no GPU).

A GL context belongs to the thread that made it current, and one created before a fork hangs the
children (moderngl issue 414), so the context is created lazily, once per process, and every later
use is checked against the process and thread that created it.
"""
import ctypes
import os
import threading

from .errors import RenderError

_context = None
_owner: tuple[int, int] | None = None  # (pid, thread id) that created _context


def gl_context(lp_threads: int | None = None):
    """The process's moderngl context, created on first call. `lp_threads` sets LP_NUM_THREADS
    (llvmpipe's rasterizer threads), which Mesa reads only when the context is created, so that
    several render workers on one machine share its cores instead of each taking all of them."""
    global _context, _owner
    here = (os.getpid(), threading.get_ident())
    if _context is not None:
        if _owner[0] != here[0]:
            raise RenderError("context_misuse", "this process was forked after its GL context was created; "
                              "start render workers with the 'spawn' method")
        if _owner[1] != here[1]:
            raise RenderError("context_misuse", "the GL context is used from a thread other than the one that "
                              "created it; keep each renderer on one thread")
        return _context
    if lp_threads:
        os.environ["LP_NUM_THREADS"] = str(int(lp_threads))
    import moderngl  # imported here so that importing the package does not load GL

    try:
        _context = moderngl.create_standalone_context(backend="egl", require=400)
    except Exception as exc:  # moderngl raises plain Exception subclasses for every EGL failure
        raise RenderError("no_gl_context", f"cannot create a headless EGL OpenGL 4.0 context: {exc}. "
                          + install_hint(str(exc))) from exc
    _owner = here
    return _context


# The Debian package of each shared library the EGL back end loads.
LIBRARY_PACKAGES = {"libGL.so": "libgl1", "libEGL.so": "libegl1", "libgbm.so": "libgbm1"}
MESA_PACKAGES = "libegl1 libgl1 libegl-mesa0 libgl1-mesa-dri libgbm1"


def install_hint(error: str) -> str:
    """What to install for a failed context: the package of the library the error names, else all
    of Mesa's headless stack."""
    for library, package in LIBRARY_PACKAGES.items():
        if library in error:
            return f"{library} is missing: install the Debian package {package} (scripts/system-packages.sh)"
    return f"Needs Mesa EGL ({MESA_PACKAGES}: scripts/system-packages.sh); EGL_PLATFORM=surfaceless may help"


class _GL:
    """The few GL entry points moderngl does not wrap: per-axis wrap modes (mirrored repeat, clamp
    to border) and the border colour, which MaterialX's address modes need, and mip levels given
    as images (moderngl writes only into levels its own mipmap generation made)."""

    TEXTURE_2D = 0x0DE1
    TEXTURE_WRAP_S = 0x2802
    TEXTURE_WRAP_T = 0x2803
    TEXTURE_BORDER_COLOR = 0x1004
    TEXTURE_MAX_LEVEL = 0x813D
    FLOAT = 0x1406
    # float32 textures of 1-4 channels: (internal format, format)
    FLOAT_FORMATS = {1: (0x822E, 0x1903), 2: (0x8230, 0x8227), 3: (0x8815, 0x1907), 4: (0x8814, 0x1908)}

    def __init__(self):
        egl = ctypes.CDLL("libEGL.so.1")
        egl.eglGetProcAddress.restype = ctypes.c_void_p
        egl.eglGetProcAddress.argtypes = [ctypes.c_char_p]
        enum, vptr = ctypes.c_uint, ctypes.POINTER(ctypes.c_float)
        self.tex_parameter_i = ctypes.CFUNCTYPE(None, enum, enum, ctypes.c_int)(
            egl.eglGetProcAddress(b"glTexParameteri"))
        self.tex_parameter_fv = ctypes.CFUNCTYPE(None, enum, enum, vptr)(
            egl.eglGetProcAddress(b"glTexParameterfv"))
        self.tex_image_2d = ctypes.CFUNCTYPE(None, enum, ctypes.c_int, ctypes.c_int, ctypes.c_int, ctypes.c_int,
                                             ctypes.c_int, enum, enum, ctypes.c_void_p)(
            egl.eglGetProcAddress(b"glTexImage2D"))

    def set_wrap(self, wrap_s: int, wrap_t: int, border: tuple[float, float, float, float]):
        """Wrap modes and border colour of the texture bound to the active unit."""
        self.tex_parameter_i(self.TEXTURE_2D, self.TEXTURE_WRAP_S, wrap_s)
        self.tex_parameter_i(self.TEXTURE_2D, self.TEXTURE_WRAP_T, wrap_t)
        self.tex_parameter_fv(self.TEXTURE_2D, self.TEXTURE_BORDER_COLOR, (ctypes.c_float * 4)(*border))

    def define_levels(self, channels: int, levels: list) -> None:
        """Levels 1, 2, ... of the float32 texture bound to the active unit from (h, w, channels)
        float32 images, and its last level set to the last of them."""
        internal, layout = self.FLOAT_FORMATS[channels]
        for level, image in enumerate(levels, start=1):
            data = image.astype("f4", copy=False).tobytes()
            self.tex_image_2d(self.TEXTURE_2D, level, internal, image.shape[1], image.shape[0], 0, layout,
                              self.FLOAT, data)
        self.tex_parameter_i(self.TEXTURE_2D, self.TEXTURE_MAX_LEVEL, len(levels))


_gl_extras: _GL | None = None


def gl_extras() -> _GL:
    """Entry points for the current context (call after gl_context())."""
    global _gl_extras
    if _gl_extras is None:
        _gl_extras = _GL()
    return _gl_extras
