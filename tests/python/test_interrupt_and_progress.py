"""Ctrl-C stops a running solve, the GIL is free during a solve, and the
progress callable is called between iterations and can stop the solve."""

import _thread
import signal
import threading
import time

import numpy as np
import pytest

import halfspace as hs

# A solve that cannot finish soon: the plain Polonsky-Keer iteration on a
# rough 512^2 surface with an unreachable tolerance and a large iteration cap.
LONG = dict(e_star=1e9, mean_pressure=1e6, boundary="periodic", solver="pk", tol=1e-15, max_iter=10**8,
            fft_planning="estimate", threads=1)


@pytest.fixture(scope="module")
def rough():
    return hs.generate.self_affine(grid=(512, 512), size=1e-3, rms_slope=0.2, seed=3)


@pytest.fixture(scope="module")
def large():
    # Plain Polonsky-Keer needs about 100 iterations of a 2048^2 transform
    # pair here: tens of seconds, so the interrupt below always lands
    # mid-solve however fast the machine (512^2 converges within a second).
    return hs.generate.self_affine(grid=(2048, 2048), size=1e-3, rms_slope=0.2, seed=3)


def test_keyboard_interrupt_stops_a_solve(large):
    # A shell starts background jobs with SIGINT ignored; Python then installs
    # no handler and interrupt_main does nothing. Give SIGINT Python's own
    # handler for this test, as an interactive session has it.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    delay = 1.0
    timer = threading.Timer(delay, _thread.interrupt_main)
    try:
        start = time.monotonic()
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            hs.solve(large, **LONG)
        stopped = time.monotonic() - start
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)
    # Stopped within the check interval (0.1 s) plus an iteration, with margin for a loaded machine.
    assert stopped < delay + 2.0, stopped
    # The process is usable afterwards: the next solve runs normally.
    again = hs.solve(hs.generate.sphere(grid=(32, 32), size=1e-3, radius=0.01), e_star=1e9, force=0.1,
                     fft_planning="estimate", threads=1)
    assert again.converged


def test_gil_is_released_during_a_solve(rough):
    counter = {"ticks": 0, "stop": False}

    def tick():
        while not counter["stop"]:
            counter["ticks"] += 1
            time.sleep(0.001)

    thread = threading.Thread(target=tick)
    thread.start()
    try:
        result = hs.solve(rough, **{**LONG, "max_iter": 60})
    finally:
        counter["stop"] = True
        thread.join()
    assert result.status == "iteration_limit"
    # The other thread ran while the solve held no GIL (60 iterations take far more than 10 ms).
    assert counter["ticks"] > 10, counter


def test_progress_is_called_every_iteration():
    calls = []
    surface = hs.generate.self_affine(grid=(64, 64), size=1e-3, rms_slope=0.1, seed=1)
    result = hs.solve(surface, e_star=1e9, mean_pressure=1e6, boundary="periodic", solver="pk-fourier",
                      fft_planning="estimate", threads=1, progress=lambda k, r: calls.append((k, r)))
    assert result.converged
    # One call per evaluation, numbered from 0 (the starting pressure) to the last iteration.
    assert [k for k, _ in calls] == list(range(len(calls)))
    assert calls[-1][0] == result.iterations
    assert np.array_equal([r for _, r in calls], result.residual_history)


def test_exception_in_progress_stops_the_solve(rough):
    class Enough(Exception):
        pass

    def progress(iteration, residual):
        if iteration == 5:
            raise Enough(f"stopped at {iteration}")

    with pytest.raises(Enough, match="stopped at 5"):
        hs.solve(rough, **LONG, progress=progress)


def test_progress_returning_false_stops_the_solve(rough):
    seen = []

    def progress(iteration, residual):
        seen.append(iteration)
        return iteration != 5

    result = hs.solve(rough, **LONG, progress=progress)
    assert result.status == "stopped"
    assert not result.converged
    assert result.iterations == 5
    assert seen == list(range(6))
    assert "stopped by the caller" in result.message


def test_progress_returning_none_goes_on():
    surface = hs.generate.self_affine(grid=(64, 64), size=1e-3, rms_slope=0.1, seed=1)
    result = hs.solve(surface, e_star=1e9, mean_pressure=1e6, boundary="periodic", solver="pk-fourier",
                      fft_planning="estimate", threads=1, progress=lambda k, r: None)
    assert result.converged


def test_progress_returning_false_ends_a_sweep(rough):
    solves = []

    def progress(iteration, residual):
        if iteration == 0:
            solves.append(0)
        return not (len(solves) == 2 and iteration == 3)

    sweep = hs.sweep(rough, e_star=1e9, mean_pressure=[1e6, 2e6, 3e6], boundary="periodic", solver="pk-fourier",
                     fft_planning="estimate", threads=1, progress=progress)
    statuses = [step.status for step in sweep.steps]
    assert statuses == ["converged", "stopped"], statuses
