"""Our Slang turned into SPIR-V by the Slang compiler that PyPI's slangpy ships, for WebGPU to draw
(bench/wgsl_images.py --target slang): the image check of the slang target (issue 24).

slangpy's Python API loads modules but hands out no target code, and its Vulkan device does not
start on lavapipe; the compiler library it ships (libslang-compiler) keeps Slang's plain C entry
points (spCreateSession, spCreateCompileRequest, spCompile, spGetEntryPointCode), which ctypes
calls: each stage compiled alone to SPIR-V (Slang writes SPIR-V 1.5: Vulkan 1.2).

Two things are changed in the binary it writes, neither in its code:
- its OpSource names Slang (source language 11), which Debian's spirv-tools and naga do not
  know: the OpSource instruction (debug information) is dropped;
- Slang puts each stage's resources in descriptor set 0; the layout our records publish (and the
  renderer binds) puts the pixel stage's in set 1, so the pixel module's DescriptorSet
  decorations are set to 1. Bindings within a set are Slang's own (the order of declaration, as
  our layout numbers them).
The record drawn is our Vulkan record of the same element with these modules in its `spirv`
(the same uniform layout, as both are WGSL's offsets)."""
import base64
import ctypes
import os
import struct
import threading

SPIRV, SOURCE_SLANG = 6, 1  # SlangCompileTarget SLANG_SPIRV, SlangSourceLanguage SLANG_SOURCE_LANGUAGE_SLANG
STAGES = {"vertex": (b"vertexMain", 1), "pixel": (b"fragmentMain", 5)}  # SlangStage VERTEX, FRAGMENT
OP_SOURCE, OP_DECORATE, DESCRIPTOR_SET = 3, 71, 34
PIXEL_SET = 1
_LOCK = threading.Lock()
_SESSION = []


def compiler():
    """(the library, a session), made once per process."""
    with _LOCK:
        if not _SESSION:
            import slangpy

            folder = os.path.dirname(slangpy.__file__)
            name = next(n for n in sorted(os.listdir(folder)) if n.startswith("libslang-compiler.so"))
            lib = ctypes.CDLL(os.path.join(folder, name))
            p = ctypes.c_void_p
            lib.spCreateSession.restype, lib.spCreateSession.argtypes = p, [ctypes.c_char_p]
            lib.spCreateCompileRequest.restype, lib.spCreateCompileRequest.argtypes = p, [p]
            lib.spSetCodeGenTarget.argtypes = [p, ctypes.c_int]
            lib.spAddTranslationUnit.argtypes = [p, ctypes.c_int, ctypes.c_char_p]
            lib.spAddTranslationUnitSourceString.argtypes = [p, ctypes.c_int, ctypes.c_char_p, ctypes.c_char_p]
            lib.spAddEntryPoint.argtypes = [p, ctypes.c_int, ctypes.c_char_p, ctypes.c_int]
            lib.spCompile.argtypes = [p]
            lib.spGetDiagnosticOutput.restype, lib.spGetDiagnosticOutput.argtypes = ctypes.c_char_p, [p]
            lib.spGetEntryPointCode.restype = p
            lib.spGetEntryPointCode.argtypes = [p, ctypes.c_int, ctypes.POINTER(ctypes.c_size_t)]
            lib.spDestroyCompileRequest.argtypes = [p]
            _SESSION.append((lib, lib.spCreateSession(None)))
        return _SESSION[0]


def compile_stage(stage: str, source: str) -> bytes:
    """The stage's SPIR-V as Slang writes it; ValueError with Slang's diagnostics when it refuses."""
    lib, session = compiler()
    entry, kind = STAGES[stage]
    with _LOCK:
        request = lib.spCreateCompileRequest(session)
        try:
            lib.spSetCodeGenTarget(request, SPIRV)
            unit = lib.spAddTranslationUnit(request, SOURCE_SLANG, b"shader")
            lib.spAddTranslationUnitSourceString(request, unit, f"{stage}.slang".encode(), source.encode())
            index = lib.spAddEntryPoint(request, unit, entry, kind)
            failed = lib.spCompile(request)
            size = ctypes.c_size_t()
            code = None if failed else lib.spGetEntryPointCode(request, index, ctypes.byref(size))
            if not code:
                raise ValueError(f"slang refused the {stage} stage: "
                                 + (lib.spGetDiagnosticOutput(request) or b"").decode(errors="replace")[:600])
            return ctypes.string_at(code, size.value)
        finally:
            lib.spDestroyCompileRequest(request)


def for_wgpu(module: bytes, stage: str) -> bytes:
    """The module without its OpSource, the pixel stage's descriptor sets moved to PIXEL_SET."""
    words = list(struct.unpack(f"<{len(module) // 4}I", module))
    out, i = words[:5], 5  # the header
    while i < len(words):
        count, opcode = words[i] >> 16, words[i] & 0xFFFF
        instruction = words[i:i + count]
        if opcode == OP_DECORATE and stage == "pixel" and instruction[2] == DESCRIPTOR_SET:
            instruction = [*instruction[:3], PIXEL_SET]
        if opcode != OP_SOURCE:
            out.extend(instruction)
        i += count
    return struct.pack(f"<{len(out)}I", *out)


def drawable(slang: dict, vulkan: dict) -> dict:
    """Our Vulkan record of the element with the SPIR-V Slang compiled from our Slang record."""
    spirv = {stage: base64.b64encode(for_wgpu(compile_stage(stage, slang["stages"][stage]), stage)).decode("ascii")
             for stage in STAGES}
    return dict(vulkan, spirv=spirv, stages=slang["stages"])
