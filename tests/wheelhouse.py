"""A local wheelhouse, built from what is installed, so pip can install moos-lint offline.

pre-commit installs a hook's repository with ``pip install .`` into a fresh
virtualenv. With ``PIP_NO_INDEX=1`` and ``PIP_FIND_LINKS`` pointing here, pip
finds the build backend (setuptools, from virtualenv's bundled wheels) and
moos-lint's runtime dependencies, repacked as wheels from this environment's
installed distributions.
"""

from __future__ import annotations

import base64
import csv
import hashlib
import io
import re
import zipfile
from importlib import metadata
from pathlib import Path

from packaging.markers import default_environment
from packaging.requirements import Requirement
from packaging.utils import canonicalize_name


class WheelhouseError(Exception):
    pass


def _tags(dist: metadata.Distribution) -> list[str]:
    text = dist.read_text("WHEEL") or ""
    tags = [line.split(":", 1)[1].strip() for line in text.splitlines() if line.startswith("Tag:")]
    if not tags:
        raise WheelhouseError(f"{dist.metadata['Name']}: no wheel tags recorded")
    return tags


def _record_hash(data: bytes) -> str:
    digest = hashlib.sha256(data).digest()
    return "sha256=" + base64.urlsafe_b64encode(digest).rstrip(b"=").decode()


def repack(dist: metadata.Distribution, out: Path) -> Path:
    """A wheel of an installed distribution, from the files its RECORD lists."""
    name = re.sub(r"[-_.]+", "_", dist.metadata["Name"])
    tags = _tags(dist)
    # the compressed tag set of a wheel file name: py3.py2-none-any
    tag = "-".join(".".join(sorted({t.split("-")[i] for t in tags})) for i in range(3))
    files = dist.files
    if not files:
        raise WheelhouseError(f"{name}: installed without a RECORD")
    target = out / f"{name}-{dist.version}-{tag}.whl"
    rows = []
    record_name = None
    with zipfile.ZipFile(target, "w", zipfile.ZIP_DEFLATED) as zf:
        for f in files:
            arc = f.as_posix()
            if arc.startswith("..") or "__pycache__" in arc or arc.endswith(".pyc"):
                continue
            if arc.endswith(".dist-info/RECORD"):
                record_name = arc
                continue
            if arc.endswith((".dist-info/INSTALLER", ".dist-info/direct_url.json")):
                continue
            path = Path(f.locate())
            if not path.is_file():
                continue
            data = path.read_bytes()
            zf.writestr(arc, data)
            rows.append((arc, _record_hash(data), str(len(data))))
        if record_name is None:
            raise WheelhouseError(f"{name}: no RECORD file")
        buf = io.StringIO()
        writer = csv.writer(buf, lineterminator="\n")
        writer.writerows([*rows, (record_name, "", "")])
        zf.writestr(record_name, buf.getvalue())
    return target


def runtime_requirements(project: str) -> list[metadata.Distribution]:
    """The installed distributions ``project`` needs at run time (no extras), recursively."""
    env = default_environment()
    env["extra"] = ""
    seen: dict[str, metadata.Distribution] = {}
    todo = [project]
    while todo:
        name = todo.pop()
        for req_text in metadata.requires(name) or []:
            req = Requirement(req_text)
            if req.marker is not None and not req.marker.evaluate(env):
                continue
            key = canonicalize_name(req.name)
            if key in seen:
                continue
            try:
                seen[key] = metadata.distribution(req.name)
            except metadata.PackageNotFoundError as exc:
                raise WheelhouseError(f"{req.name} is not installed") from exc
            todo.append(req.name)
    return list(seen.values())


def bundled_setuptools() -> list[Path]:
    """virtualenv's bundled setuptools wheels (the build backend)."""
    try:
        import virtualenv
    except ImportError as exc:
        raise WheelhouseError("virtualenv is not installed") from exc
    embed = Path(virtualenv.__file__).parent / "seed" / "wheels" / "embed"
    return sorted(embed.glob("setuptools-*.whl"))


def build(project: str, out: Path) -> Path:
    out.mkdir(parents=True, exist_ok=True)
    backends = bundled_setuptools()
    if not backends:
        raise WheelhouseError("virtualenv bundles no setuptools wheel")
    for wheel in backends:
        (out / wheel.name).write_bytes(wheel.read_bytes())
    for dist in runtime_requirements(project):
        repack(dist, out)
    return out
