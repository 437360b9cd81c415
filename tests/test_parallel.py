"""The one parallel map: same results in the same order on every backend, errors that keep
their type, and a Ctrl-C that leaves no process behind.

The process pool and the Dask cluster are the real ones (a ``ProcessPoolExecutor`` and a
``dask.distributed.LocalCluster`` on this machine), not mocks: what is tested is that jobs
and their exceptions cross process boundaries and come back in order.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time
from pathlib import Path

import psutil
import pytest

from shaftline import parallel
from shaftline.errors import InputError, SolverFailure

ROOT = Path(__file__).resolve().parents[1]


def slow_square(x: int) -> tuple[int, int]:
    """x^2 and the process that computed it; later items finish first (reversed sleep)."""
    time.sleep(0.02 * (5 - x % 5))
    return x * x, os.getpid()


def refuse(x: int) -> int:
    if x == 3:
        raise InputError("load_y", float(x), "N", "anything but 3")
    if x == 4:
        raise SolverFailure("did not settle")
    return x


@pytest.fixture(scope="module")
def scheduler():
    """A real Dask cluster of two single-threaded worker processes on this machine."""
    from dask.distributed import LocalCluster

    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster:
        yield cluster.scheduler_address


def test_every_backend_returns_the_serial_results_in_input_order(scheduler):
    items = list(range(12))
    serial = parallel.map(slow_square, items, backend="serial")
    assert [r for r, _ in serial] == [x * x for x in items]
    assert {pid for _, pid in serial} == {os.getpid()}
    pooled = parallel.map(slow_square, items, workers=2, chunksize=2)
    assert [r for r, _ in pooled] == [r for r, _ in serial]
    assert os.getpid() not in {pid for _, pid in pooled}  # really elsewhere
    on_dask = parallel.map(slow_square, items, scheduler=scheduler)
    assert [r for r, _ in on_dask] == [r for r, _ in serial]
    assert os.getpid() not in {pid for _, pid in on_dask}


def test_a_client_of_the_callers_is_used_and_left_open(scheduler):
    """Issue 12: a Dask cluster "when the user passes a scheduler address or a
    dask.distributed.Client" — the caller's client runs the jobs (same results, on its workers) and
    is still the caller's, open, afterwards; a closed one is a one-line input error."""
    from dask.distributed import Client

    items = list(range(8))
    with Client(scheduler) as client:
        on_client = parallel.map(slow_square, items, scheduler=client)
        assert [r for r, _ in on_client] == [x * x for x in items]
        assert os.getpid() not in {pid for _, pid in on_client}
        with parallel.Pool(scheduler=client) as pool:
            assert pool.map(abs, [-1, -2]) == [1, 2] and pool.map(abs, [-3]) == [3]
        assert client.status == "running" and client.submit(abs, -4).result() == 4
    closed = r"^scheduler = 'dask.distributed.Client': allowed a running dask.distributed Client \(this one is closed\)"
    with pytest.raises(InputError, match=closed):
        parallel.map(abs, [1], scheduler=client)


def test_progress_counts_items_as_jobs_finish():
    told: list[tuple[int, int]] = []
    parallel.map(slow_square, range(7), workers=2, chunksize=3, progress=lambda d, t: told.append((d, t)))
    assert sorted(d for d, _ in told) == [d for d, _ in told]  # counts only grow
    assert told[-1] == (7, 7) and {t for _, t in told} == {7} and len(told) == 3  # jobs of 3, 3 and 1


@pytest.mark.parametrize("backend", ["serial", "process", "dask"])
def test_a_worker_error_reaches_the_caller_with_its_type(backend, scheduler):
    where = {"scheduler": scheduler} if backend == "dask" else {"backend": backend, "workers": 2}
    with pytest.raises(InputError) as error:
        parallel.map(refuse, [1, 2, 3], **where)
    assert (error.value.field, error.value.value, error.value.unit) == ("load_y", 3.0, "N")
    assert str(error.value) == "load_y = 3 N: allowed anything but 3"
    with pytest.raises(SolverFailure, match="did not settle"):
        parallel.map(refuse, [4, 1], **where)


def test_bad_choices_are_one_line_input_errors():
    with pytest.raises(InputError, match="backend = 'threads': allowed one of serial, process, dask"):
        parallel.map(abs, [1], backend="threads")
    with pytest.raises(InputError, match="workers = 0"):
        parallel.map(abs, [1], workers=0)
    with pytest.raises(InputError, match="chunksize = 0"):
        parallel.map(abs, [1], chunksize=0)
    with pytest.raises(InputError, match="scheduler"):
        parallel.map(abs, [1], backend="process", scheduler="tcp://127.0.0.1:8786")
    assert parallel.map(abs, [], workers=2) == []


def test_a_scheduler_that_does_not_answer_is_an_input_error(monkeypatch):
    monkeypatch.setattr(parallel, "_CONNECT_TIMEOUT", 1.0)
    with pytest.raises(InputError, match=r"^scheduler = 'tcp://127.0.0.1:9': allowed the address of a running Dask"):
        parallel.map(abs, [1, 2], scheduler="tcp://127.0.0.1:9")


@pytest.mark.parametrize("answer", [b"", b"HTTP/1.1 200 OK\r\n\r\n" * 4])
def test_a_port_that_is_not_a_dask_scheduler_fails_after_the_time_out(monkeypatch, answer):
    """A port that accepts the connection but does not speak Dask's protocol (a dashboard's HTTP
    port, given by mistake: silent, or bytes Dask reads as a frame length) used to make Client
    wait for ever or raise MemoryError; now a one-line InputError within the time-out."""
    import socket
    import threading

    monkeypatch.setattr(parallel, "_CONNECT_TIMEOUT", 1.0)
    server = socket.create_server(("127.0.0.1", 0))
    address = f"tcp://127.0.0.1:{server.getsockname()[1]}"
    accepted: list[socket.socket] = []

    def serve() -> None:
        while True:
            try:
                connection, _ = server.accept()
            except OSError:
                return
            accepted.append(connection)
            connection.sendall(answer)

    threading.Thread(target=serve, daemon=True).start()
    try:
        start = time.perf_counter()
        with pytest.raises(InputError, match=r"^--scheduler = .*allowed the address of a running Dask scheduler"):
            parallel.check_scheduler(address, "--scheduler")
        assert time.perf_counter() - start < 8.0
    finally:
        server.close()
        for connection in accepted:
            connection.close()


@pytest.mark.parametrize("address", ["garbage", "http://127.0.0.1:8786", "", "tcp://127.0.0.1"])
def test_an_address_dask_cannot_read_is_an_input_error(address):
    """Dask raises ValueError for these; the user gets the one line naming the option."""
    with pytest.raises(InputError, match=r"^--scheduler = .*allowed the address of a running Dask scheduler"):
        parallel.check_scheduler(address, "--scheduler")
    with pytest.raises(InputError, match=r"^scheduler = "):
        parallel.map(abs, [1, 2], scheduler=address)


def test_a_scheduler_without_workers_is_told_not_waited_for():
    """A real scheduler with no worker: jobs would queue for ever without a word."""
    from dask.distributed import LocalCluster

    with LocalCluster(n_workers=0, dashboard_address=":0") as cluster:
        start = time.perf_counter()
        with pytest.raises(InputError, match="at least one worker"):
            parallel.check_scheduler(cluster.scheduler_address, timeout=1.0)
        assert time.perf_counter() - start < 10.0


def test_a_worker_address_is_told_apart_from_the_scheduler(scheduler, tmp_path):
    """The address of a real worker (or of its nanny) given as the scheduler: one line saying it is
    not a scheduler and naming the worker's scheduler, not Dask's internal TypeError; from the
    command line exit 2 before anything is read or written."""
    from dask.distributed import Client

    with Client(scheduler) as client:
        workers = client.scheduler_info()["workers"]
    worker, info = next(iter(workers.items()))
    with pytest.raises(InputError) as error:
        parallel.check_scheduler(worker, "--scheduler")
    text = str(error.value)
    assert text.startswith(f"--scheduler = '{worker}': allowed the address of a running Dask scheduler")
    assert f"this is a Dask worker, not a scheduler; its scheduler is {scheduler}" in text
    assert "TypeError" not in text and "\n" not in text
    with pytest.raises(InputError, match="this is a Dask nanny .*, not a scheduler"):
        parallel.map(abs, [1, 2], scheduler=info["nanny"])
    from tests.conftest import invoke

    out = tmp_path / "out"
    result = invoke("design", "slopes", str(ROOT / "examples" / "ntua_slope_design.toml"), "--scheduler", worker,
                    "--out", str(out))  # fmt: skip
    assert result.exit_code == 2 and len(result.stderr.strip().splitlines()) == 1, result.stderr
    assert "not a scheduler" in result.stderr and not out.exists()


@pytest.fixture
def stopped_scheduler():
    """A real ``dask scheduler`` process, frozen with SIGSTOP when the test says (it then accepts
    connections, as the kernel does for it, but answers nothing: a hung or overloaded scheduler)."""
    import socket

    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    command = [sys.executable, "-m", "distributed.cli.dask_scheduler", "--host", "127.0.0.1", "--port", str(port),
               "--no-dashboard"]  # fmt: skip
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    try:
        assert process.stderr is not None
        for line in process.stderr:  # its log says when it listens
            if "Scheduler at:" in line:
                break
        address = f"tcp://127.0.0.1:{port}"

        def freeze(frozen: bool = True) -> None:
            process.send_signal(signal.SIGSTOP if frozen else signal.SIGCONT)

        yield address, freeze
    finally:
        process.send_signal(signal.SIGCONT)
        process.terminate()
        process.wait(timeout=30)


def test_a_scheduler_that_stops_answering_ends_after_the_time_out(monkeypatch, stopped_scheduler):
    """A real scheduler frozen before the connection, or between the probe and Dask's client (whose
    handshake has no time-out): one line naming the address, the time-out and what to check, within
    the time-out and its grace; never a hang or a bare TimeoutError."""
    address, freeze = stopped_scheduler
    monkeypatch.setattr(parallel, "_CONNECT_TIMEOUT", 1.0)
    probe = parallel._probe

    def then_freeze(where: str, timeout: float) -> object:
        answer = probe(where, timeout)  # the real scheduler answered: freeze it now
        freeze()
        return answer

    monkeypatch.setattr(parallel, "_probe", then_freeze)
    start = time.perf_counter()
    with pytest.raises(InputError) as error:
        parallel.check_scheduler(address, "--scheduler")
    assert time.perf_counter() - start < 8.0  # 2 x 1 s + 1 s grace for the client, and the start
    text = str(error.value)
    assert text.startswith(f"--scheduler = '{address}': allowed the address of a running Dask scheduler")
    assert "no answer in Dask's protocol within 1 s: check that it is the scheduler's address" in text
    # thawed, the scheduler answers the client given up on: that client is closed, not left open
    freeze(False)
    deadline = time.monotonic() + 20.0
    while any(t.name == "shaftline-dask-connect" for t in threading.enumerate()) and time.monotonic() < deadline:
        time.sleep(0.1)
    from distributed import Client

    mine = [c for c in list(Client._instances) if c.scheduler and c.scheduler.address == address]
    assert all(c.status == "closed" for c in mine)
    freeze()
    monkeypatch.setattr(parallel, "_probe", probe)
    start = time.perf_counter()
    with pytest.raises(InputError, match="no answer in Dask's protocol within 1 s: check"):
        parallel.map(abs, [1, 2], scheduler=address)  # frozen from the start
    assert time.perf_counter() - start < 4.0


def test_a_backend_name_is_checked_even_when_the_work_runs_here():
    from shaftline.film import sweep
    from shaftline.film.study import BearingCase
    from tests.conftest import make_bearing

    bearing = make_bearing(1.0, axial_nodes=11, circumferential_nodes=36)
    case = BearingCase("one", bearing.geometry, bearing.operating, bearing.options, load_y=-3e3)
    with pytest.raises(InputError, match="backend = 'foo'"):
        sweep([case], backend="foo")


def _descendants(pid: int) -> list[psutil.Process]:
    try:
        return psutil.Process(pid).children(recursive=True)
    except psutil.NoSuchProcess:
        return []


def _gone(process: psutil.Process) -> bool:
    try:
        return process.status() == psutil.STATUS_ZOMBIE
    except psutil.NoSuchProcess:
        return True


def _interrupt(command: list[str], workers: int) -> tuple[subprocess.CompletedProcess[str], list[psutil.Process]]:
    """Start ``command``, wait until ``workers`` pool workers run, send SIGINT; the result and
    the descendants there were."""
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src") + os.pathsep + os.environ.get("PYTHONPATH", "")}
    child = subprocess.Popen(command, cwd=ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    before: list[psutil.Process] = []
    try:
        deadline = time.monotonic() + 60.0
        # The fork server and the workers (forkserver start), or the workers alone (spawn).
        while len(_descendants(child.pid)) < workers + 1 and time.monotonic() < deadline and child.poll() is None:
            time.sleep(0.1)
        time.sleep(0.5)
        before = _descendants(child.pid)
        assert len(before) >= workers, f"the pool did not start: {child.poll()} {child.stderr and child.stderr.read()}"
        child.send_signal(signal.SIGINT)
        stdout, stderr = child.communicate(timeout=10.0)
    except subprocess.TimeoutExpired:
        # Not stopped: end what this test started (left-over workers hold the pipes open).
        for process in [*before, psutil.Process(child.pid)]:
            if not _gone(process):
                process.kill()
        child.communicate()
        raise
    return subprocess.CompletedProcess(command, child.returncode, stdout, stderr), before


def _assert_all_gone(processes: list[psutil.Process]) -> None:
    deadline = time.monotonic() + 5.0
    while not all(_gone(p) for p in processes) and time.monotonic() < deadline:
        time.sleep(0.1)
    assert all(_gone(p) for p in processes), [p.pid for p in processes if not _gone(p)]


def test_ctrl_c_stops_a_pool_at_once_and_leaves_no_process():
    """Jobs of 60 s each on two workers: SIGINT to the parent ends it in seconds, with
    KeyboardInterrupt, and its fork server and workers are gone."""
    script = textwrap.dedent(
        """
        import time
        from shaftline import parallel

        if __name__ == "__main__":
            try:
                parallel.map(time.sleep, [60.0] * 4, workers=2)
            except KeyboardInterrupt:
                print("interrupted")
                raise SystemExit(130)
        """
    )
    start = time.monotonic()
    result, before = _interrupt([sys.executable, "-c", script], workers=2)
    assert time.monotonic() - start < 30.0
    assert result.returncode == 130 and result.stdout.strip() == "interrupted", result.stderr
    assert "Traceback" not in result.stderr  # the workers ignore SIGINT: no trace from each
    _assert_all_gone(before)


def test_ctrl_c_in_a_run_on_the_pool_exits_130_and_leaves_no_process(tmp_path):
    """``shaftline run`` spreading bearing variants over two workers: exit 130, one line, no output."""
    # Each variant its own bore, so its own film problem: six jobs for the pool.
    variants = "".join(
        f'\n[[bearing.variants]]\nname = "v{k}"\n[[bearing.variants.bore]]\nlength_fraction = 1.0\n'
        f"slope_ratio = {0.05 * (k + 1):.2f}\n"
        for k in range(6)
    )
    case = tmp_path / "case.toml"
    text = (ROOT / "examples" / "ntua_stern_tube.toml").read_text()
    # A finer grid: each variant takes seconds, so the interrupt lands while the pool works.
    text = text.replace("axial_nodes = 100", "axial_nodes = 200").replace(
        "circumferential_nodes = 60", "circumferential_nodes = 240"
    )
    head, _, _ = text.partition("[[bearing.variants]]")
    case.write_text(head + variants)
    out = tmp_path / "out"
    command = [sys.executable, "-m", "shaftline.cli", "run", str(case), "--out", str(out), "--workers", "2"]
    result, before = _interrupt(command, workers=2)
    assert result.returncode == 130, result.stderr
    assert result.stderr.strip().splitlines()[-1] == "interrupted: nothing was written"
    assert not out.exists()
    _assert_all_gone(before)


def test_pool_keeps_its_workers_between_calls():
    """A Pool's second map runs on the processes of its first (what they built stays)."""
    with parallel.Pool(workers=2) as pool:
        first = set(pool.map(_pid, range(6)))
        second = set(pool.map(_pid, range(6)))
    assert second <= first and os.getpid() not in first
    with parallel.Pool(backend="serial") as pool:
        assert pool.map(abs, [-1, -2], chunksize=2) == [1, 2]


def _pid(_: int) -> int:
    time.sleep(0.05)
    return os.getpid()


def test_pool_workers_run_blas_single_threaded():
    """Workers get one BLAS/OpenMP thread each (one worker per core), the caller keeps its own."""
    before = {name: os.environ.get(name) for name in parallel.SINGLE_THREADED}
    with parallel.Pool(workers=2) as pool:
        seen = pool.map(_thread_settings, range(2))
    assert all(s == parallel.SINGLE_THREADED for s in seen)
    assert {name: os.environ.get(name) for name in parallel.SINGLE_THREADED} == before


def _thread_settings(_: int) -> dict[str, str | None]:
    return {name: os.environ.get(name) for name in parallel.SINGLE_THREADED}


def _fresh_process(script: str, folder: Path) -> subprocess.CompletedProcess[str]:
    """``script`` run as a file (its functions pickle by name) in a new interpreter on this source
    tree: its first pool starts a fork server."""
    path = folder / "script.py"
    path.write_text(textwrap.dedent(script))
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src") + os.pathsep + os.environ.get("PYTHONPATH", "")}
    return subprocess.run([sys.executable, str(path)], cwd=ROOT, env=env, capture_output=True, text=True, timeout=120)


def test_work_here_while_the_workers_start_and_not_after(tmp_path):
    """``work_here``: in a process whose fork server is not running yet, the caller solves jobs
    from the end of the list (the last always) while the workers start, and the workers the
    first ones; the results are the serial ones in input order. Once the fork server runs,
    workers start in milliseconds and the jobs all go to them."""
    script = """
        import json, os, time
        from shaftline import parallel

        def job(x):
            time.sleep(0.02 * (1 + x % 3))
            return x * x, os.getpid()

        if __name__ == "__main__":
            items = list(range(40))
            first = parallel.map(job, items, workers=2, work_here=True)
            second = parallel.map(job, items, workers=2, work_here=True)
            print(json.dumps({"me": os.getpid(), "first": first, "second": second}))
        """
    result = _fresh_process(script, tmp_path)
    assert result.returncode == 0, result.stderr
    out = json.loads(result.stdout)
    for run in ("first", "second"):
        assert [r for r, _ in out[run]] == [x * x for x in range(40)]
    first_pids = [pid for _, pid in out["first"]]
    assert first_pids[-1] == out["me"]  # the last job is the caller's
    assert any(pid != out["me"] for pid in first_pids)  # and the workers took the first ones
    assert out["me"] not in {pid for _, pid in out["second"]}


def test_workers_of_a_film_program_start_with_the_compiled_sweeps_loaded(tmp_path):
    """A program that has imported the film package (not solved anything yet): its fork server
    preloads the film solver's compiled kernel, so each worker finds it loaded instead of
    loading numba at its first film solution (0.3-0.6 s a worker). A program that has not
    imported the film package does not pay for it."""
    script = """
        import json
        {imports}

        def loaded(_):
            import sys
            return "shaftline.film._relaxation_kernel" in sys.modules

        if __name__ == "__main__":
            print(json.dumps(parallel.map(loaded, range(2), workers=2)))
        """
    for imports, expected in (
        ("from shaftline import parallel", [False, False]),
        ("import shaftline.film; from shaftline import parallel", [True, True]),
    ):
        result = _fresh_process(script.format(imports=imports), tmp_path)
        assert result.returncode == 0, result.stderr
        assert json.loads(result.stdout) == expected


def test_an_error_in_a_job_solved_here_reaches_the_caller_with_its_type(tmp_path):
    script = """
        from shaftline import parallel
        from shaftline.errors import InputError

        def refuse(x):
            if x == 3:
                raise InputError("load_y", float(x), "N", "anything but 3")
            return x

        if __name__ == "__main__":
            try:
                parallel.map(refuse, [0, 1, 2, 3], workers=2, work_here=True)  # 3, the last, solved here
            except InputError as error:
                print(type(error).__name__, error)
        """
    result = _fresh_process(script, tmp_path)
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("InputError load_y = 3"), result.stdout


def test_ctrl_c_while_this_process_works_leaves_no_process():
    """SIGINT while this process solves its own job (work_here): it stops handing out jobs,
    ends the workers it started and exits 130, no process left."""
    script = textwrap.dedent(
        """
        import time
        from shaftline import parallel

        if __name__ == "__main__":
            try:
                parallel.map(time.sleep, [60.0] * 4, workers=2, work_here=True)
            except KeyboardInterrupt:
                print("interrupted")
                raise SystemExit(130)
        """
    )
    start = time.monotonic()
    result, before = _interrupt([sys.executable, "-c", script], workers=2)
    assert time.monotonic() - start < 30.0
    assert result.returncode == 130 and result.stdout.strip() == "interrupted", result.stderr
    _assert_all_gone(before)
