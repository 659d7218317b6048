"""What the fuzz test (tests/faults) and the long runs (bench/fuzz.py) share: the cases of each
kind, how an answer to one is judged, and the peak memory of a server's generator children.

Crate cases are real `.usdc` files, written with usd-core from the USD test scenes, truncated
and with bytes flipped (a fixed seed names every case), each sent as the root layer of a usdz."""
import random
import tempfile
import threading
from pathlib import Path

GENERATOR_MODULE = "service.workers.gen_worker"
USDZ = {"content-type": "model/vnd.usdz+zip"}
ERROR_KEYS = {"code", "message", "where"}


def base_crates() -> list[bytes]:
    """The crate files the cases corrupt: each test scene alone, and both in one layer."""
    from pxr import Usd

    from usd_in.scenes import preview_surface_stage, standard_surface_stage

    def both(stage):
        preview_surface_stage(stage)
        standard_surface_stage(stage)

    crates = []
    with tempfile.TemporaryDirectory(prefix="crate-cases-") as folder:
        for n, build in enumerate((preview_surface_stage, standard_surface_stage, both)):
            stage = Usd.Stage.CreateInMemory()
            build(stage)
            path = Path(folder) / f"scene{n}.usdc"
            assert stage.GetRootLayer().Export(str(path))
            crates.append(path.read_bytes())
    return crates


def corrupt(rng: random.Random, crate: bytes) -> tuple[str, bytes]:
    """A truncation, a few flipped bytes (anywhere, or in the header and table of contents that
    every read starts from), or both; with what was done, for a failure's message."""
    kind = rng.choice(("truncate", "flip", "flip_toc", "both"))
    data = bytearray(crate)
    if kind in ("truncate", "both"):
        data = data[:rng.randrange(1, len(data))]  # not empty: usd-core's zip writer cannot add an empty file
    if kind in ("flip", "flip_toc", "both") and data:
        toc = int.from_bytes(crate[16:24], "little")
        for _ in range(rng.randint(1, 8)):
            at = rng.randrange(len(data)) if kind != "flip_toc" or toc >= len(data) else \
                rng.choice((rng.randrange(min(24, len(data))), rng.randrange(toc, len(data))))
            data[at] ^= 1 << rng.randrange(8) if rng.random() < 0.5 else rng.randrange(1, 256)
    return f"{kind} to {len(data)} bytes", bytes(data)


def usdz(crate: bytes, folder: Path) -> bytes:
    """A usdz whose only member (its root layer) is this crate file."""
    from pxr import Sdf

    member, package = folder / "scene.usdc", folder / "case.usdz"
    member.write_bytes(crate)
    package.unlink(missing_ok=True)
    writer = Sdf.ZipFileWriter.CreateNew(str(package))
    writer.AddFile(str(member), "scene.usdc")
    writer.Save()
    return package.read_bytes()


def corrupted_crates(count: int, seed: int):
    """(label, crate file) for `count` cases of this seed: the same cases every run."""
    rng = random.Random(seed)
    crates = base_crates()
    for n in range(count):
        what, data = corrupt(rng, rng.choice(crates))
        yield f"case {n}: {what}", data


def crate_cases(count: int, seed: int):
    """(label, usdz body) for `count` cases of this seed."""
    with tempfile.TemporaryDirectory(prefix="crate-cases-") as folder:
        for label, data in corrupted_crates(count, seed):
            yield label, usdz(data, Path(folder))


def judge(response) -> str | None:
    """Why an answer breaks the contract (None when it keeps it): a 5xx, or a refusal that is not
    the error object with a code, a message and a where."""
    if response.status_code >= 500:
        return f"{response.status_code}: {response.text[:500]}"
    if response.status_code == 200:
        return None
    body = response.json()
    if not 400 <= response.status_code < 500 or not isinstance(body.get("error"), dict) \
            or not ERROR_KEYS <= set(body["error"]) or not body["error"]["code"] or not body["error"]["message"]:
        return f"{response.status_code} without the error object: {response.text[:500]}"
    return None


class ChildPeakMemory:
    """The largest peak resident size (VmHWM) any generator child of the server reached, sampled
    from /proc every few milliseconds while it runs (a child's peak is read before it exits)."""

    def __init__(self, server_pid: int, pause_s: float = 0.02):
        self.server_pid, self.pause_s = server_pid, pause_s
        self.peak_kib = 0
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)

    def __enter__(self) -> "ChildPeakMemory":
        self._thread.start()
        return self

    def __exit__(self, *_):
        self._stop.set()
        self._thread.join(timeout=5)
        self.sample()

    @property
    def peak_mib(self) -> float:
        return self.peak_kib / 1024

    def sample(self) -> None:
        from processes import cmdline, descendants, peak_rss_kib

        for pid in descendants(self.server_pid):
            if f"-m {GENERATOR_MODULE}" in cmdline(pid):
                self.peak_kib = max(self.peak_kib, peak_rss_kib(pid) or 0)  # 0: gone since the listing

    def _run(self) -> None:
        while not self._stop.wait(self.pause_s):
            self.sample()
