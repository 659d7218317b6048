"""Issue 21, item 2: every child process bounded in memory, and nothing of a killed child left on
disk. Two real documents that allocate a lot: a usdz whose crate file has one count of its FIELDS
section raised to 2^28 (usd-core allocates gigabytes opening it: 5.2 GB in 7 s under a 6 GiB
address-space limit, measured), and a material whose texture is a 4096 x 4096 PNG of 235 kB
(decoded to float32 with its mipmaps: 1.4 GB resident at its peak). The server's limits are set
low enough that both cross them, and high enough for everything else.

The server runs with a TMPDIR of its own, so that "nothing left" is checked where its children
write, and nowhere that other processes of the machine share."""
import os
import signal
import struct
import threading
from pathlib import Path

import numpy as np
import pytest

from required_tools import require_module

require_module("pxr", "usd-core: pip install -e '.[usd]', which scripts/test.sh does")

from pxr import Gf, Sdf, Usd, UsdShade  # noqa: E402

from faults_testing import processes, wait_ready  # noqa: E402
from service.workers import memory  # noqa: E402
from service_testing import DOCS, Server, assert_error, document, is_png, wait_until  # noqa: E402

from shadergen.render.imageio import encode_png  # noqa: E402

GEN, RENDER = "service.workers.gen_worker", "service.workers.render_worker"
GENERATE_MIB, RENDER_MIB = 400, 600
USDZ = {"content-type": "model/vnd.usdz+zip"}
pytestmark = pytest.mark.usefixtures("renderer_required")


def material_stage(path: Path, texture: str | None = None) -> None:
    stage = Usd.Stage.CreateNew(str(path))
    material = UsdShade.Material.Define(stage, "/Looks/Red")
    surface = UsdShade.Shader.Define(stage, "/Looks/Red/Surface")
    surface.CreateIdAttr("UsdPreviewSurface")
    surface.CreateInput("roughness", Sdf.ValueTypeNames.Float).Set(0.4)
    colour = surface.CreateInput("diffuseColor", Sdf.ValueTypeNames.Color3f)
    if texture is None:
        colour.Set(Gf.Vec3f(0.8, 0.2, 0.1))
    else:
        image = UsdShade.Shader.Define(stage, "/Looks/Red/Texture")
        image.CreateIdAttr("UsdUVTexture")
        image.CreateInput("file", Sdf.ValueTypeNames.Asset).Set(texture)
        colour.ConnectToSource(image.ConnectableAPI(), "rgb")
    material.CreateSurfaceOutput().ConnectToSource(surface.ConnectableAPI(), "surface")
    stage.GetRootLayer().Save()


def zipped(folder: Path, *members: str) -> bytes:
    writer = Sdf.ZipFileWriter.CreateNew(str(folder / "upload.usdz"))
    for name in members:
        writer.AddFile(str(folder / name), name)
    writer.Save()
    return (folder / "upload.usdz").read_bytes()


def crate_section(data: bytes, name: str) -> int:
    """Where a section of a usdc file starts, from its table of contents."""
    toc = struct.unpack_from("<Q", data, 16)[0]  # after the 8-byte magic and the 8-byte version
    for i in range(struct.unpack_from("<Q", data, toc)[0]):
        section, start, _ = struct.unpack_from("<16sQQ", data, toc + 8 + 32 * i)
        if section.rstrip(b"\0") == name.encode():
            return start
    raise AssertionError(f"no {name} section")


def hungry_usdz(folder: Path) -> bytes:
    folder.mkdir()
    material_stage(folder / "scene.usdc")
    data = bytearray((folder / "scene.usdc").read_bytes())
    struct.pack_into("<Q", data, crate_section(data, "FIELDS"), 1 << 28)  # the section's field count
    (folder / "scene.usdc").write_bytes(data)
    return zipped(folder, "scene.usdc")


def big_texture() -> bytes:
    checks = (np.indices((4096, 4096)).sum(0) // 256 % 2).astype("f4")
    return encode_png(np.stack([checks, checks * 0.5, 1 - checks, np.ones_like(checks)], -1))


def textured_usdz(folder: Path) -> bytes:
    folder.mkdir()
    (folder / "big.png").write_bytes(big_texture())
    material_stage(folder / "scene.usdc", "big.png")
    return zipped(folder, "scene.usdc", "big.png")


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("childmemory")
    textures = tmp / "textures"
    textures.mkdir()
    (textures / "big.png").write_bytes(big_texture())
    (textures / "checker.png").write_bytes((DOCS / "checker.png").read_bytes())
    (tmp / "tmp").mkdir()
    srv = Server(tmp, workers=1, render_workers=1, env={
        "SHADERGEN_GENERATE_MEMORY_MIB": str(GENERATE_MIB), "SHADERGEN_RENDER_MEMORY_MIB": str(RENDER_MIB),
        "SHADERGEN_TEXTURE_ROOTS": str(textures), "TMPDIR": str(tmp / "tmp")})
    srv.tmp = tmp / "tmp"
    yield srv
    srv.close()


def temporary_files(server) -> list[str]:
    """What children wrote and left: anything in their folders, and any job folder wherever it is.
    A folder a live child removes while it is listed is listed again (CI saw rglob race one)."""
    for _ in range(20):
        try:
            left = [*server.tmp.glob("shadergen-child-*/**/*"), *server.tmp.rglob("shadergen-usdz-*"),
                    *server.tmp.rglob("shadergen-job-*")]
        except FileNotFoundError:
            continue
        return sorted({str(p.relative_to(server.tmp)) for p in left})
    raise AssertionError("the children's folders kept changing while listed")


def child_folder(pid: int) -> Path:
    environ = dict(entry.split("=", 1) for entry in
                   Path(f"/proc/{pid}/environ").read_bytes().decode().split("\0") if "=" in entry)
    return Path(environ["TMPDIR"])


def one(server, module: str) -> int:
    pids = wait_until(lambda: processes(server, module), 60, module)
    assert len(pids) == 1, pids
    return pids[0]


def test_generator_over_its_limit_answers_413_alone_and_is_replaced(server, tmp_path):
    client = server.client
    wait_ready(client)
    before = one(server, GEN)
    err = assert_error(client.post("/v1/generate", content=hungry_usdz(tmp_path / "hungry"), headers=USDZ),
                       413, "too_large")
    assert f"limit of {GENERATE_MIB} MiB" in err["message"], err
    after = one(server, GEN)
    assert after != before
    assert server.log_text().count("over its limit") == 1  # killed once: not tried again on the fresh child
    r = client.post("/v1/generate", content=zipped_plain(tmp_path / "plain"), headers=USDZ)
    assert r.status_code == 200, r.text
    assert processes(server, RENDER)  # the render worker never noticed
    assert not temporary_files(server), temporary_files(server)
    assert "Traceback" not in server.log_text()


def zipped_plain(folder: Path) -> bytes:
    folder.mkdir()
    material_stage(folder / "scene.usdc")
    return zipped(folder, "scene.usdc")


def test_render_worker_over_its_limit_answers_413_and_is_replaced(server):
    client = server.client
    wait_ready(client)
    before = one(server, RENDER)
    big = document("textured.mtlx").replace("checker.png", "big.png")
    err = assert_error(client.post("/v1/thumbnails", json={"document": big, "size": 32}), 413, "too_large")
    assert f"limit of {RENDER_MIB} MiB" in err["message"], err
    assert one(server, RENDER) != before
    r = client.post("/v1/thumbnails", json={"document": document("textured.mtlx"), "size": 32})
    assert r.status_code == 200 and is_png(r.content, 32), r.text
    assert not temporary_files(server), temporary_files(server)


def killed_mid_job(server, module: str, send, prefix: str):
    """Send a request from a thread, SIGKILL the child as soon as its job folder (named `prefix`)
    exists, and return the answer and the killed child's folder."""
    pid = one(server, module)
    folder = child_folder(pid)
    answer = {}
    thread = threading.Thread(target=lambda: answer.update(response=send()))
    thread.start()
    try:
        wait_until(lambda: list(folder.glob(prefix + "*")), 60, f"{prefix} in {folder}", pause_s=0.002)
        os.kill(pid, signal.SIGKILL)
    finally:
        thread.join(timeout=120)
    return answer["response"], folder


def test_children_killed_mid_job_leave_no_files(server, tmp_path):
    client = server.client
    wait_ready(client)
    # the generator unpacks the usdz into shadergen-usdz-*; killed there, the job is tried again on
    # a fresh child, which goes over its limit
    hungry = hungry_usdz(tmp_path / "hungry")
    response, folder = killed_mid_job(
        server, GEN, lambda: client.post("/v1/generate", content=hungry, headers=USDZ), "shadergen-usdz-")
    assert_error(response, 413, "too_large")
    assert not folder.exists()
    # the render worker writes the package into shadergen-job-* and the texture it decodes beside
    package = textured_usdz(tmp_path / "textured")
    wait_ready(client)
    response, folder = killed_mid_job(
        server, RENDER, lambda: client.post("/v1/thumbnails", content=package, headers=USDZ), "shadergen-job-")
    assert_error(response, 413, "too_large")
    assert not folder.exists()
    assert not temporary_files(server), temporary_files(server)
    wait_ready(client)


def test_a_packages_textures_leave_the_render_worker_with_its_job(server, tmp_path):
    """A usdz upload's textures are read from its own package, in a job folder removed when the
    job ends, so no later job can ask for them again; the render worker's texture cache kept them
    all the same (about 21 MB resident each for a 1024 x 1024 texture) until its budget pushed
    them out: every client's images held after its request, and a worker full of them answered
    an innocent thumbnail 413 (its 600 MiB limit reached after some twenty packages). Each
    thumbnail here is another client's package with a texture of its own."""
    from hostile_packages import png

    client = server.client
    wait_ready(client)
    worker = one(server, RENDER)
    resident = []
    for i in range(24):
        folder = tmp_path / f"client{i}"
        folder.mkdir()
        (folder / "t.png").write_bytes(png(1024, 1024, (10 * i, 20, 30)))
        material_stage(folder / "scene.usdc", "t.png")
        r = client.post("/v1/thumbnails", params={"size": 16}, content=zipped(folder, "scene.usdc", "t.png"),
                        headers=USDZ)
        assert r.status_code == 200 and is_png(r.content, 16), (i, r.text)
        resident.append(memory.resident_bytes(worker) >> 20)
    assert one(server, RENDER) == worker
    # (MiB) flat once the allocator has its working set (measured: 223 after the first job, 337 from
    # the seventh to the last), which swings by up to 40 from one job to the next (a job's peak
    # against the one before it failed 1 run in 9 with no leak); before, each job added its
    # texture, about 21 MiB: 250 more twelve jobs on, which the last jobs' least shows
    assert min(resident[-4:]) - max(resident[8:12]) < 32, resident


def test_the_render_pool_keeps_no_package_after_its_job(server, tmp_path):
    """The render pool keeps finished jobs for polling (ten minutes, up to 1024 of them), and each
    kept its request, whose usdz package is the upload, base64: 2.7 MB for a 2 MiB upload. The
    pool's own process (no child under a memory limit) grew by that with every usdz thumbnail
    (575 MiB resident after 192 of them, measured, and 2.8 GB at 1024 jobs); now a finished job
    keeps its outcome alone."""
    client = server.client
    wait_ready(client)
    pool = one(server, "service.jobs.pool_server")
    folder = tmp_path / "padded"
    folder.mkdir()
    material_stage(folder / "scene.usdc")
    (folder / "padding.bin").write_bytes(os.urandom(2 * 1024 * 1024 - 8192))  # the upload near the body limit
    package = zipped(folder, "scene.usdc", "padding.bin")
    resident = []
    for i in range(40):
        # (a size of its own: the same thumbnail again would be answered from the store, without a job)
        r = client.post("/v1/thumbnails", params={"size": 16 + i}, content=package, headers=USDZ)
        assert r.status_code == 200 and is_png(r.content, 16 + i), (i, r.text)
        resident.append(memory.resident_bytes(pool) >> 20)
    assert resident[-1] - resident[4] < 40, resident  # MiB; before, 2.7 MB more with every job
