"""The one way shaftline runs many independent jobs: serially, on a local process pool or a
Dask cluster, through :func:`map`.

Sweeps, searches and robustness tables all go through :func:`map` (a :class:`Pool` for one
call), so a notebook, the command line and a cluster run the same code. The backends are
named in :data:`BACKENDS` (the style of SciPy's ``method=`` choices):

``"serial"``
    In this process, one item after the other (the reference: the others give the same
    results in the same order).
``"process"`` (default)
    A ``concurrent.futures.ProcessPoolExecutor`` on this machine, one worker process per
    core unless ``workers`` says. Workers start with ``forkserver`` where the platform has
    it (Linux), else ``spawn``, never ``fork``: numba's and OpenMP's thread pools do not
    survive a fork of a process that has started them, and a forked child would inherit
    whatever solver state the parent holds. With ``work_here`` the caller solves jobs too
    while its workers start slowly (the first pool of a process waits about 0.7 s for its
    fork server to import the solver, which would leave a core idle).
``"dask"``
    A ``dask.distributed`` cluster: the scheduler at ``scheduler`` (``"tcp://host:8786"``), the
    caller's own ``dask.distributed.Client`` given as ``scheduler``,
    or a ``LocalCluster`` started for the call. Needs the optional extra ``parallel``
    (``pip install shaftline[parallel]``) and shaftline installed on every worker.

The function and the items must pickle (module-level functions, dataclasses; a
:class:`shaftline.film.JournalBearing` pickles as its problem). Results come back in the
order of the items whatever order the workers finish in. An exception raised by the
function in a worker reaches the caller with its own type (an
:class:`~shaftline.errors.InputError` stays one), and the other jobs are stopped. Ctrl-C
(``KeyboardInterrupt``) stops the workers before it reaches the caller, so no process is
left behind; pool workers ignore SIGINT themselves, so a Ctrl-C that reaches the whole
process group interrupts only the parent, which then ends them.
"""

from __future__ import annotations

import multiprocessing
import os
import signal
import sys
import threading
from collections.abc import Callable, Sequence
from concurrent.futures import FIRST_EXCEPTION, Future, ProcessPoolExecutor, wait
from typing import TYPE_CHECKING, Any, TypeVar

from shaftline.errors import InputError

if TYPE_CHECKING:
    from distributed import Client

__all__ = ["BACKENDS", "Pool", "available_workers", "backend_name", "check_scheduler", "map"]

T = TypeVar("T")
R = TypeVar("R")

#: Seconds to wait for a Dask scheduler to answer before the address is called wrong.
_CONNECT_TIMEOUT = 10.0
#: Seconds a run waits for the first worker to join a scheduler that has none.
_WORKER_TIMEOUT = 60.0
#: ``progress(done, total)``: told, in the calling process, how many items are finished.
ProgressCallback = Callable[[int, int], None]


def available_workers() -> int:
    """Cores this process may run on (its CPU affinity where the platform tells it), >= 1."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not on Linux
        return max(1, os.cpu_count() or 1)


def _run_batch(function: Callable[[T], R], batch: list[T]) -> list[R]:
    """One job of a worker: the function on each item of a batch, in order."""
    return [function(item) for item in batch]


def _serial(
    function: Callable[[Any], Any], batches: list[list[Any]], on_batch: Callable[[int], None]
) -> list[list[Any]]:
    results = []
    for index, batch in enumerate(batches):
        results.append(_run_batch(function, batch))
        on_batch(index)
    return results


def _ignore_sigint() -> None:
    """Pool workers leave Ctrl-C to the parent, which ends them (no traceback from each)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)


#: Thread pools of BLAS and OpenMP set to one thread in the workers: one worker per core, so
#: threads of their own would only compete for the cores (Dask's nanny sets the same).
SINGLE_THREADED = {"OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}


#: Compiled kernels of the film solver (numba: 0.5-0.9 s and about 100 MiB to load), imported by
#: the fork server of a process that uses the film package, so that its workers find them loaded
#: instead of each loading them at its first film solution. The server imports them while this
#: process goes on (it survives an ImportError of a preloaded module, e.g. no numba; the kernels
#: compile without numba's cache where none can be written rather than raise).
_FILM_KERNELS = ("shaftline.film._relaxation_kernel",)


#: Whether this process has started its fork server (its workers then start in milliseconds).
_FORK_SERVER: list[bool] = []


def _context(function: Callable[[Any], Any]) -> tuple[Any, bool]:
    """``forkserver`` where available (fast start, no inherited threads), else ``spawn``; and
    whether the workers start slowly (``spawn``, or the fork server started by this call).

    The fork server imports the module of ``function`` before it forks the first worker
    (the solver modules take about half a second to import), so each worker starts with it
    loaded. The server is started once per process, with :data:`SINGLE_THREADED` in its
    environment (and so in every worker's); later calls reuse it as it is.
    """
    if "forkserver" not in multiprocessing.get_all_start_methods():
        return multiprocessing.get_context("spawn"), True
    context = multiprocessing.get_context("forkserver")
    module = getattr(getattr(function, "func", function), "__module__", None)
    # Every worker runs the caller's script again (as "__mp_main__": the fork server of Python
    # 3.11 does not preload it, its "main_path" is never passed), and that script imports what
    # it imported here: 0.2 s a worker a pool for a script that loads the case reader. So the
    # fork server preloads this process's shaftline modules too, and the workers find them.
    loaded = sorted(
        name
        for name in sys.modules
        if (name == "shaftline" or name.startswith("shaftline.")) and not name.endswith(".__main__")
    )
    preload = ([module] if module and module not in ("__main__", "__mp_main__") else []) + loaded
    if any(name.startswith("shaftline.film") for name in loaded):
        preload += list(_FILM_KERNELS)
    context.set_forkserver_preload(list(dict.fromkeys(preload)))
    from multiprocessing import forkserver

    saved = {name: os.environ.get(name) for name in SINGLE_THREADED}
    os.environ.update(SINGLE_THREADED)
    try:
        forkserver.ensure_running()  # started here, it keeps this environment
    finally:
        for name, value in saved.items():
            if value is None:
                os.environ.pop(name, None)
            else:
                os.environ[name] = value
    slow = not _FORK_SERVER
    _FORK_SERVER.append(True)
    return context, slow


def _stop(executor: ProcessPoolExecutor) -> None:
    """End a pool now: drop the queued jobs and terminate the workers (no orphans)."""
    # The executor has no public way to end running jobs before Python 3.14
    # (terminate_workers); its process table is the documented-in-source way to reach them.
    processes = list((getattr(executor, "_processes", None) or {}).values())
    executor.shutdown(wait=False, cancel_futures=True)
    for process in processes:
        if process.is_alive():
            process.terminate()
    for process in processes:
        process.join(timeout=5.0)
        if process.is_alive():
            process.kill()
            process.join(timeout=5.0)


def _new_executor(function: Callable[[Any], Any], count: int) -> tuple[ProcessPoolExecutor, bool]:
    """A pool of ``count`` workers, and whether they start slowly (:func:`_context`)."""
    context, slow = _context(function)
    return ProcessPoolExecutor(max_workers=count, mp_context=context, initializer=_ignore_sigint), slow


def _gather_process(
    executor: ProcessPoolExecutor,
    function: Callable[[Any], Any],
    batches: list[list[Any]],
    on_batch: Callable[[int], None],
    work_here: bool = False,
) -> list[list[Any]]:
    """Run the batches on a pool and collect them in order (the pool is the caller's to stop).

    With ``work_here`` the caller solves batches too, from the end of the list, until the first
    worker delivers: the first pool of a process waits for its fork server to start and import
    the solver (about a second), and this process would otherwise wait through it with a core
    idle. The batches are handed to the pool from the front by a thread meanwhile (handing out
    the first ones waits for the fork server), so the two ends meet wherever the work does.
    """
    results: list[list[Any]] = [[] for _ in batches]
    futures: dict[Future[list[Any]], int] = {}
    lock = threading.Lock()
    ends = [0, len(batches)]  # next batch from the front (the pool), one past the last (here)
    failure: list[BaseException] = []
    stop = threading.Event()

    def from_front() -> int | None:
        with lock:
            if stop.is_set() or ends[0] >= ends[1]:
                return None
            ends[0] += 1
            return ends[0] - 1

    def from_back() -> int | None:
        with lock:
            if ends[1] <= ends[0]:
                return None
            ends[1] -= 1
            return ends[1]

    def submit() -> None:
        try:
            while (index := from_front()) is not None:
                future = executor.submit(_run_batch, function, batches[index])
                with lock:
                    futures[future] = index
        except BaseException as error:  # told to the caller's thread below
            failure.append(error)

    def delivered() -> bool:
        with lock:
            return any(future.done() for future in futures)

    if work_here and len(batches) > 1:
        handing_out = threading.Thread(target=submit, name="shaftline-pool-submit", daemon=True)
        handing_out.start()
        try:
            while not delivered():
                index = from_back()
                if index is None:
                    # All handed out: take back a queued one from the end, if any is still queued.
                    with lock:
                        queued = sorted(futures, key=futures.__getitem__, reverse=True)
                    taken = next((future for future in queued if future.cancel()), None)
                    if taken is None:
                        break
                    with lock:
                        index = futures.pop(taken)
                results[index] = _run_batch(function, batches[index])
                on_batch(index)
        except BaseException:
            # Ctrl-C or the function's error: no more workers started, and every one started is
            # in the pool's table when the caller ends them.
            stop.set()
            handing_out.join()
            raise
        handing_out.join()
    else:
        submit()
    if failure:
        raise failure[0]
    pending = set(futures)
    while pending:
        finished, pending = wait(pending, return_when=FIRST_EXCEPTION)
        # Deliver in a fixed order within one wake-up: the caller's progress then reads the same.
        for future in sorted(finished, key=futures.__getitem__):
            results[futures[future]] = future.result()  # re-raises the worker's exception
            on_batch(futures[future])
    return results


def _user_client(scheduler: Any) -> bool:
    """``scheduler`` is a ``dask.distributed.Client`` the caller made (not an address)."""
    if scheduler is None or isinstance(scheduler, str):
        return False
    try:
        from distributed import Client
    except ImportError:
        return False
    return isinstance(scheduler, Client)


def _dask_client(workers: int, scheduler: str | Client | None) -> tuple[Any, Any]:
    """A client of the scheduler at ``scheduler`` (checked to have a worker), the caller's own
    client (checked the same way), or one of a ``LocalCluster`` of ``workers`` processes
    started for it; and that cluster (or None)."""
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError:
        raise InputError(
            "backend", "dask", "", "an installed dask.distributed (pip install 'shaftline[parallel]')"
        ) from None
    if _user_client(scheduler):
        assert not isinstance(scheduler, str) and scheduler is not None
        where = str(getattr(scheduler.scheduler, "address", None) or "dask.distributed.Client")
        if scheduler.status != "running":
            raise InputError(
                "scheduler", where, "", f"a running dask.distributed Client (this one is {scheduler.status})"
            )
        _wait_for_workers(scheduler, where, "scheduler", _WORKER_TIMEOUT)
        return scheduler, None
    if scheduler is not None:
        assert isinstance(scheduler, str)
        client = _connect(scheduler, "scheduler")
        try:
            # Jobs sent to a scheduler without workers would wait for ever, silently.
            _wait_for_workers(client, scheduler, "scheduler", _WORKER_TIMEOUT)
        except BaseException:
            client.close()
            raise
        return client, None
    # One single-threaded worker process per core: the film solver is single-threaded
    # and holds the GIL in Python, so threads would only queue behind each other.
    cluster = LocalCluster(
        n_workers=workers,
        threads_per_worker=1,
        processes=True,
        # A free port: None does not turn the dashboard off (dask/distributed#8136), and
        # the default 8787 warns when another cluster holds it.
        dashboard_address=":0",
    )
    return Client(cluster, timeout=_CONNECT_TIMEOUT), cluster


def _gather_dask(
    client: Any, function: Callable[[Any], Any], batches: list[list[Any]], on_batch: Callable[[int], None]
) -> list[list[Any]]:
    from dask.distributed import as_completed

    futures: list[Any] = []
    try:
        futures = [client.submit(_run_batch, function, batch, pure=False) for batch in batches]
        where = {future.key: index for index, future in enumerate(futures)}
        results: list[list[Any]] = [[] for _ in batches]
        for future in as_completed(futures):
            index = where[future.key]
            results[index] = future.result()  # re-raises the worker's exception with its type
            on_batch(index)
        return results
    finally:
        if futures:
            client.cancel(futures)


#: The backends by name (``backend=`` of :func:`map` and :class:`Pool`).
BACKENDS = ("serial", "process", "dask")


def backend_name(backend: str | None, workers: int | None, scheduler: str | Client | None) -> str:
    """The backend that :func:`map` uses for these arguments, checked (raises
    :class:`InputError` naming ``"backend"``, ``"workers"`` or ``"scheduler"``)."""
    name = backend if backend is not None else ("dask" if scheduler is not None else "process")
    if name not in BACKENDS:
        raise InputError("backend", name, "", "one of " + ", ".join(BACKENDS))
    if workers is not None and (isinstance(workers, bool) or not isinstance(workers, int) or workers < 1):
        raise InputError("workers", workers if isinstance(workers, int) else repr(workers), "", "an integer >= 1")
    if scheduler is not None and name != "dask":
        shown = scheduler if isinstance(scheduler, str) else repr(scheduler)
        raise InputError("scheduler", shown, "", f"no scheduler with backend {name!r} (only with 'dask')")
    return name


def check_scheduler(scheduler: str, field: str = "scheduler", timeout: float = _CONNECT_TIMEOUT) -> None:
    """Connect to the Dask scheduler at ``scheduler`` and wait up to ``timeout`` seconds for a
    worker, so that a wrong address or an empty cluster is told at once, not after the case is
    read (the command line calls it before solving). Raises :class:`InputError` naming
    ``field``."""
    client = _connect(scheduler, field)
    try:
        _wait_for_workers(client, scheduler, field, timeout)
    finally:
        client.close()


def _connect(scheduler: str, field: str, timeout: float | None = None) -> Any:
    """A Dask client of the scheduler at ``scheduler``, or an :class:`InputError` within
    ``timeout`` seconds (default :data:`_CONNECT_TIMEOUT`)."""
    timeout = _CONNECT_TIMEOUT if timeout is None else timeout
    try:
        from dask.distributed import Client
    except ImportError:
        raise InputError(
            field, scheduler, "", "a machine with dask.distributed (pip install 'shaftline[parallel]')"
        ) from None
    allowed = _ADDRESS
    if not isinstance(scheduler, str) or not scheduler.strip():
        raise InputError(field, repr(scheduler), "", allowed)
    from distributed.comm.addressing import parse_address, parse_host_port
    from distributed.comm.registry import get_backend

    try:
        # Read the address first: a Client made for one it cannot read starts (and may leave)
        # an event-loop thread before it fails.
        scheme, location = parse_address(scheduler)
        get_backend(scheme)
        if scheme in ("tcp", "tls"):
            parse_host_port(location)
    except ValueError as error:
        raise InputError(field, scheduler, "", f"{allowed} ({error})") from None
    try:
        identity = _probe(scheduler, timeout)
    except (KeyboardInterrupt, SystemExit):
        raise
    except TimeoutError:
        raise InputError(field, scheduler, "", _silent(timeout)) from None
    except OSError as error:  # nothing listens there, or the host is unknown or unreachable
        raise InputError(field, scheduler, "", _silent(timeout, str(error))) from None
    except Exception as error:
        # ValueError/TypeError: an address Dask cannot parse;
        # MemoryError and others: a service that sends bytes Dask reads as a frame length.
        raise InputError(field, scheduler, "", f"{allowed} ({type(error).__name__}: {error})") from None
    kind = str(identity.get("type", "")) if isinstance(identity, dict) else ""
    if "Scheduler" not in kind:
        raise InputError(field, scheduler, "", f"{allowed} ({_not_a_scheduler(kind, identity)})")
    try:
        # the client's own time-out first, with room for its retries
        return _bounded(lambda: Client(scheduler, timeout=timeout), 2.0 * timeout + 1.0, field, scheduler, timeout)
    except (TimeoutError, OSError):
        raise InputError(field, scheduler, "", _silent(timeout)) from None
    except InputError:
        raise
    except Exception as error:
        raise InputError(field, scheduler, "", f"{allowed} ({type(error).__name__}: {error})") from None


#: What ``--scheduler`` must be (the "allowed" of its errors).
_ADDRESS = "the address of a running Dask scheduler, e.g. tcp://10.0.0.5:8786"


def _silent(timeout: float, why: str = "") -> str:
    """The "allowed" of an address that did not answer as a scheduler in time: what to check."""
    why = why or f"no answer in Dask's protocol within {timeout:g} s"
    return (
        f"{_ADDRESS} ({why}: check that it is the scheduler's address, port 8786 unless it was started with "
        "another, not its dashboard's 8787; that the scheduler is running and not overloaded; and that this "
        "machine may reach it, firewall or VPN)"
    )


def _not_a_scheduler(kind: str, identity: Any) -> str:
    """Why a Dask server that answered is not a scheduler, and where its scheduler is."""
    if kind in ("Worker", "Nanny"):
        where = identity.get("scheduler") if kind == "Worker" else None
        role = "a Dask worker" if kind == "Worker" else "a Dask nanny (the process that watches a worker)"
        tail = f"; its scheduler is {where}" if where else "; give its scheduler's address"
        return f"this is {role}, not a scheduler{tail}"
    return f"this Dask server is a {kind or 'server that does not say what it is'}, not a scheduler"


def _bounded(make: Callable[[], R], seconds: float, field: str, scheduler: str, timeout: float) -> R:
    """``make()`` in a thread of its own (what it raises is raised here), given up after
    ``seconds``: then an :class:`InputError` saying that the scheduler did not answer within
    ``timeout``.

    A Dask ``Client`` bounds its TCP connection by ``timeout`` but not the handshake and the
    identity request that follow: a scheduler that stops answering between the probe and the
    client (overloaded, suspended) would hold the command for ever. The thread is a daemon,
    so one left waiting does not hold the process at exit, and a client it makes after the
    caller gave up is closed (not left registered as Dask's default client).
    """
    box: dict[str, Any] = {}
    lock = threading.Lock()

    def run() -> None:
        try:
            value = make()
        except BaseException as error:  # handed to the caller's thread
            box["error"] = error
            return
        with lock:
            if not box.get("abandoned"):
                box["value"] = value
                return
        _close_quietly(value)  # a client made after the caller gave up on it: not left open

    thread = threading.Thread(target=run, name="shaftline-dask-connect", daemon=True)
    thread.start()
    thread.join(seconds)
    with lock:
        if thread.is_alive():
            box["abandoned"] = True
            raise InputError(field, scheduler, "", _silent(timeout))
    if "error" in box:
        raise box["error"]
    return box["value"]


def _close_quietly(value: Any) -> None:
    try:
        value.close()
    except Exception:  # the scheduler that hung may be gone by now; nothing to tell anyone
        pass


def _probe(scheduler: str, timeout: float) -> Any:
    """Open one connection to ``scheduler``, ask who it is and close it, all within ``timeout``
    seconds; the answer is the server's identity (``{"type": "Scheduler", ...}``).

    ``Client(address, timeout=...)`` bounds the TCP connection but not Dask's handshake: on a
    port that accepts the connection and then waits for something else (a Dask dashboard's HTTP
    port, which users give by mistake) it waits for ever. Asking for the identity also tells a
    worker's address (which users give by mistake too: Client then fails inside Dask with a
    TypeError) from a scheduler's. The probe runs in a thread of its own so that it also works
    where an event loop is already running (a notebook).
    """
    import asyncio
    from concurrent.futures import ThreadPoolExecutor

    from distributed.comm import connect

    async def ask() -> Any:
        comm = await connect(scheduler, timeout=timeout)
        try:
            await comm.write({"op": "identity", "reply": True})
            return await comm.read()
        finally:
            comm.abort()

    async def once() -> Any:
        try:
            return await asyncio.wait_for(ask(), timeout)
        except TimeoutError:
            raise TimeoutError(f"no answer in Dask's protocol within {timeout:g} s") from None

    with ThreadPoolExecutor(1) as thread:
        return thread.submit(asyncio.run, once()).result()


def _wait_for_workers(client: Any, scheduler: str, field: str, timeout: float) -> None:
    try:
        # bounded as well: Dask's first request of it (the scheduler's identity) has no time-out
        _bounded(lambda: client.wait_for_workers(1, timeout=timeout), timeout + _CONNECT_TIMEOUT, field, scheduler,
                 _CONNECT_TIMEOUT)  # fmt: skip
    except TimeoutError:
        raise InputError(
            field, scheduler, "", f"a Dask scheduler with at least one worker (none joined within {timeout:g} s)"
        ) from None


def _batched(
    items: Sequence[T], chunksize: int, progress: ProgressCallback | None
) -> tuple[list[list[T]], Callable[[int], None]]:
    """The items in jobs of ``chunksize`` (checked) and the callback that counts them done."""
    if isinstance(chunksize, bool) or not isinstance(chunksize, int) or chunksize < 1:
        raise InputError("chunksize", chunksize, "", "an integer >= 1")
    listed = list(items)
    total = len(listed)
    batches = [listed[start : start + chunksize] for start in range(0, total, chunksize)]
    done = 0

    def on_batch(index: int) -> None:
        nonlocal done
        done += len(batches[index])
        if progress is not None:
            progress(done, total)

    return batches, on_batch


class Pool:
    """Workers kept for several :meth:`map` calls: the generations of a search, the rounds of
    a sweep. Each call of :func:`map` starts its workers and ends them; a pool starts them at
    its first call and keeps them (and whatever they have built, e.g. a film solver's
    factorisations) until :meth:`close` or the end of a ``with`` block.

    Parameters
    ----------
    backend, workers, scheduler
        As for :func:`map`; ``workers`` (default one per core) is the pool's size.

    Examples
    --------
    >>> from shaftline import parallel
    >>> with parallel.Pool(backend="serial") as pool:
    ...     pool.map(abs, [-1, 2]), pool.map(abs, [-3])
    ([1, 2], [3])
    """

    def __init__(
        self, backend: str | None = None, workers: int | None = None, scheduler: str | Client | None = None
    ) -> None:
        self.backend = backend_name(backend, workers, scheduler)
        if self.backend == "process" and workers == 1:
            self.backend = "serial"
        self.workers = workers
        self.scheduler = scheduler
        #: Workers to start: ``workers``, else one per core (:func:`map` caps it at its jobs).
        self.size = workers or available_workers()
        self._executor: ProcessPoolExecutor | None = None
        self._client: Any = None
        self._cluster: Any = None

    def __enter__(self) -> Pool:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def map(
        self,
        function: Callable[[T], R],
        items: Sequence[T],
        *,
        chunksize: int = 1,
        progress: ProgressCallback | None = None,
        work_here: bool = False,
    ) -> list[R]:
        """``[function(item) for item in items]`` on the pool's workers, in order (as :func:`map`).

        An error or Ctrl-C ends the workers (the next call starts new ones) and is raised."""
        batches, on_batch = _batched(items, chunksize, progress)
        if not batches:
            return []
        if self.backend == "serial":
            results = _serial(function, batches, on_batch)
        elif self.backend == "process":
            slow = False
            if self._executor is None:
                self._executor, slow = _new_executor(function, self.size)
            try:
                # The caller works only while the workers start slowly: on running workers (a
                # kept pool, or a fork server that runs) it would only take a core from them.
                results = _gather_process(self._executor, function, batches, on_batch, work_here=work_here and slow)
            except BaseException:
                _stop(self._executor)
                self._executor = None
                raise
        else:
            if self._client is None:
                self._client, self._cluster = _dask_client(self.size, self.scheduler)
            results = _gather_dask(self._client, function, batches, on_batch)
        return [result for batch in results for result in batch]

    def close(self) -> None:
        """End the workers (a local cluster too; a remote scheduler's workers, and a client the
        caller gave, stay)."""
        if self._executor is not None:
            self._executor.shutdown(wait=True)
            self._executor = None
        if self._client is not None:
            if self._client is not self.scheduler:  # the caller's own client stays theirs
                self._client.close()
            self._client = None
        if self._cluster is not None:
            self._cluster.close()
            self._cluster = None


def map(
    function: Callable[[T], R],
    items: Sequence[T],
    *,
    backend: str | None = None,
    workers: int | None = None,
    scheduler: str | Client | None = None,
    chunksize: int = 1,
    progress: ProgressCallback | None = None,
    work_here: bool = False,
) -> list[R]:
    """``[function(item) for item in items]``, spread over cores or a cluster.

    Parameters
    ----------
    function : callable
        Applied to each item; must pickle for ``"process"`` and ``"dask"`` (a module-level
        function or a ``functools.partial`` of one).
    items : sequence
        The inputs; must pickle for ``"process"`` and ``"dask"``.
    backend : {"serial", "process", "dask"}, optional
        Where to run (:data:`BACKENDS`); default ``"dask"`` when ``scheduler`` is given,
        else ``"process"``.
    workers : int, optional
        Worker processes: default one per core of this machine (``"process"``; a
        ``LocalCluster`` for ``"dask"``), never more than there are jobs. With ``workers=1``
        the items run here, serially: a pool of one would only add its start-up. Ignored
        with a ``scheduler`` (the cluster has its workers).
    scheduler : str or dask.distributed.Client, optional
        Address of a running Dask scheduler, e.g. ``"tcp://10.0.0.5:8786"``, or a client of
        one made by the caller (used as it is and left open: e.g. a dask-jobqueue or
        dask-kubernetes cluster's ``Client(cluster)``).
    chunksize : int
        Items sent to a worker per job (>= 1): more amortise the transfer of short jobs.
    progress : callable, optional
        ``progress(done, total)`` in this process as items finish (per job of
        ``chunksize`` items).
    work_here : bool
        ``"process"`` only: this process solves jobs too, from the end of the list, while
        the pool's workers start and until the first of them delivers (their start waits
        for the fork server, about half a second for the first pool of a process). For
        jobs that give the same result wherever they run; those solved here see this
        process's BLAS threads and state.

    Returns
    -------
    list
        The results in the order of ``items``.

    Raises
    ------
    InputError
        ``"backend"``, ``"workers"`` or ``"chunksize"`` out of range; and whatever
        ``function`` raises, with its own type.

    Examples
    --------
    >>> from shaftline import parallel
    >>> parallel.map(abs, [-2, 3, -5], backend="serial")
    [2, 3, 5]
    """
    pool = Pool(backend, workers, scheduler)
    jobs = len(_batched(items, chunksize, None)[0])
    # a pool for one call: no more workers than jobs (a LocalCluster or process each costs a start)
    pool.size = max(1, min(pool.size, jobs))
    with pool:
        return pool.map(function, items, chunksize=chunksize, progress=progress, work_here=work_here)
