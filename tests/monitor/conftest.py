"""Fixtures of the monitor tests: a real PostgreSQL server for the trend store and the verbs."""

from __future__ import annotations

import os
import shutil
import socket
import subprocess
import tempfile
from pathlib import Path

import pytest


def _server_binaries() -> Path | None:
    for candidate in sorted(Path("/usr/lib/postgresql").glob("*/bin"), reverse=True):
        if (candidate / "initdb").exists() and (candidate / "pg_ctl").exists():
            return candidate
    found = shutil.which("initdb")
    return Path(found).parent if found and shutil.which("pg_ctl") else None


@pytest.fixture(scope="module")
def postgres_url():
    """A PostgreSQL server of Debian's package, started for this module on a Unix socket in a
    temporary folder and stopped after it (as the user ``postgres`` when the tests run as
    root, which initdb refuses; the folder is then its own, outside pytest's, which only
    root may enter)."""
    binaries = _server_binaries()
    if binaries is None:
        pytest.skip("no PostgreSQL server here (Debian's package postgresql; `make test` installs it where it can)")
    folder = Path(tempfile.mkdtemp(prefix="shaftline-postgres-"))
    prefix: list[str] = []
    if os.geteuid() == 0:
        if shutil.which("runuser") is None:
            pytest.skip("running as root without runuser: initdb cannot run as root")
        prefix = ["runuser", "-u", "postgres", "--"]
        shutil.chown(folder, "postgres")
    data = folder / "data"
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    run = dict(check=True, capture_output=True, text=True, timeout=120)
    initdb, pg_ctl = str(binaries / "initdb"), str(binaries / "pg_ctl")
    options = f"-p {port} -k {folder} -c listen_addresses='' -c fsync=off"
    try:
        subprocess.run([*prefix, initdb, "-D", str(data), "-A", "trust", "-U", "shaftline", "--no-sync"], **run)
        log = str(folder / "log")
        subprocess.run([*prefix, pg_ctl, "-D", str(data), "-o", options, "-l", log, "-w", "start"], **run)
        yield f"postgresql+psycopg://shaftline@/postgres?host={folder}&port={port}"
    finally:
        subprocess.run([*prefix, pg_ctl, "-D", str(data), "-m", "immediate", "stop"], capture_output=True, timeout=120)
        shutil.rmtree(folder, ignore_errors=True)


@pytest.fixture(scope="session")
def simulated_example(tmp_path_factory):
    """``shaftline monitor simulate examples/monitor_rig.toml --out DIR --json -`` run once for the tests that
    read its output (about 15 s: six lined equilibria and the slow roll): the command's result and DIR."""
    from tests.conftest import invoke

    example = Path(__file__).resolve().parents[2] / "examples" / "monitor_rig.toml"
    out = tmp_path_factory.mktemp("monitor_example") / "out"
    result = invoke("monitor", "simulate", str(example), "--out", str(out), "--json", "-")
    return result, out
