"""simulate releases the GIL while it integrates, and Ctrl-C (SIGINT) stops it at the next
record with KeyboardInterrupt, after which Python's own handler is back."""
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import hmfnet


def test_gil_released_while_integrating():
    net = hmfnet.generate.er(2000, mean_degree=20, seed=2)
    ticks = []
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    start = time.monotonic()
    hmfnet.simulate(net, seed=1, K=[1.0], T=100, transient=10, threads=1)
    end = time.monotonic()
    done.set()
    counter.join()
    # The counter ran during the integration (a held GIL would freeze it for the whole run).
    inside = [t for t in ticks if start + 0.1 * (end - start) < t < end - 0.1 * (end - start)]
    assert len(inside) >= 5, (len(inside), end - start)


def test_ctrl_c_raises_keyboard_interrupt_and_restores_the_handler(tmp_path):
    checkpoint = tmp_path / "ck.h5"
    script = textwrap.dedent(f"""
        import os, signal, sys, time
        import hmfnet
        net = hmfnet.generate.er(2000, mean_degree=20, seed=2)
        try:
            hmfnet.simulate(net, seed=1, K=[1.0], T=10**6, transient=0, threads=1,
                            checkpoint={str(checkpoint)!r})
        except KeyboardInterrupt as e:
            print("interrupted:", e, flush=True)
        else:
            sys.exit(1)
        # Python's own handler is back at the C level: a second SIGINT is a KeyboardInterrupt
        # raised by the interpreter (hmfnet's handler would only set its flag).
        try:
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(5)
        except KeyboardInterrupt:
            print("python handler restored", flush=True)
            sys.exit(0)
        sys.exit(2)
    """)
    p = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True,
                         env=os.environ.copy())
    # The first checkpoint of a one-K run is written after 5 s of integration (the default
    # interval; none is written as the first K starts), when the run's SIGINT handler is in
    # place: only then is the signal the run's to take. T = 10^6 keeps the run going after it.
    deadline = time.monotonic() + 60
    while not checkpoint.exists() and time.monotonic() < deadline and p.poll() is None:
        time.sleep(0.05)
    assert checkpoint.exists(), "the run never started"
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=60)
    assert p.returncode == 0, out
    assert "SIGINT after" in out and "--resume" in out
    assert "python handler restored" in out
