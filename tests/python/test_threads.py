# The GIL is released while a mesh is computed, and Ctrl-C (SIGINT) cancels a run cleanly.
#
# Both tests are deterministic without timing: sys.setswitchinterval(1000) stops CPython from
# handing the GIL to another thread by time slicing (1000 s), so the second thread can run only when
# the first one releases the GIL on purpose. If tetrahedralize held the GIL, the second thread could
# not run until all of the first thread's work was done, and the tests would fail; no sleep or
# timeout decides anything.
import os
import signal
import sys
import threading

import pytest

import sweepcdt
from conftest import shared_file

RUNS = 200  # upper bound on the first thread's work; the released GIL lets the other thread in during run 1


@pytest.fixture
def no_time_slicing():
    old = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)
    yield
    sys.setswitchinterval(old)


def test_a_second_thread_runs_while_a_mesh_is_computed(shared_data, no_time_slicing):
    points, triangles = sweepcdt.read_surface(shared_file(shared_data, "off/icosahedron.off"))
    started, other_ran = threading.Event(), threading.Event()
    runs = []

    def compute():
        started.set()
        for i in range(RUNS):
            sweepcdt.tetrahedralize(points, triangles)
            runs.append(i)
            if other_ran.is_set():
                return

    worker = threading.Thread(target=compute)
    # This (main) thread holds the GIL; it gives it up in wait() and gets it back only when the
    # worker releases it, which the worker's Python code never does by itself (no time slicing).
    worker.start()
    started.wait()
    other_ran.set()
    worker.join()
    assert len(runs) < RUNS, "the other thread could not run while meshes were computed: the GIL was held"


def test_ctrl_c_cancels_a_run_and_the_next_one_works(shared_data, no_time_slicing):
    points, triangles = sweepcdt.read_surface(shared_file(shared_data, "stl_binary/spot.stl"))
    started = threading.Event()

    def press_ctrl_c():
        # Runs once the main thread has released the GIL, i.e. inside tetrahedralize (see above).
        started.wait()
        os.kill(os.getpid(), signal.SIGINT)

    killer = threading.Thread(target=press_ctrl_c)
    killer.start()
    completed = 0
    with pytest.raises(KeyboardInterrupt):
        started.set()
        for _ in range(RUNS):
            sweepcdt.tetrahedralize(points, triangles)
            completed += 1
    killer.join()
    assert completed < RUNS
    # Nothing is left broken: the next run completes.
    assert len(sweepcdt.tetrahedralize(points, triangles).tetrahedra) > 0
