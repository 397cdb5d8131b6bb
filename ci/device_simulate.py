#!/usr/bin/env python3
"""The device check's end-to-end test of `hmfnet simulate --device cuda` (ci/device_check.sh),
with the CLI that ci/device_pack_cli.sh packed on the CPU machine:

  1. the same points (every <R>_t, SEM, energy error and momentum drift, per replica) and step
     counts as `--device cpu`, compared exactly (--json prints doubles to round-trip precision):
     float64 and float32, leapfrog and yoshida4, a K per replica (--K-across-replicas);
  2. a checkpoint written by one device and resumed on the other (SIGTERM once the checkpoint of
     the second K exists, then --resume): the points of the uninterrupted run, both ways;
  3. the rate of both on one larger network (stored entries x replicas x steps / s), and the
     device's name and the CPU threads beside it.

Prints one line per case and a last line "simulate: N cases, M failed"; exits 1 if any failed.
Usage: device_simulate.py PACKED_CLI_DIR WORK_DIR
HMFNET_SIMULATE_DEVICE=cpu runs every case with the CPU in the device's place (ci/device_prepare.sh
does, to try the script and the packed CLI where there is no GPU).
"""
import json
import os
import signal
import subprocess
import sys
import time

cli, work = sys.argv[1], sys.argv[2]
device = os.environ.get("HMFNET_SIMULATE_DEVICE", "cuda")
os.makedirs(work, exist_ok=True)
failures = []
cases = 0


def hmfnet(*args, check=True):
    done = subprocess.run([os.path.join(cli, "run"), "hmfnet", *map(str, args)],
                          capture_output=True, text=True)
    if check and done.returncode != 0:
        raise RuntimeError(f"hmfnet {' '.join(map(str, args))}: exit {done.returncode}: "
                           f"{done.stderr.strip()}")
    return done


def run_json(*args):
    return json.loads(hmfnet(*args, "--json", "--quiet").stdout)


def case(name, ok, note=""):
    global cases
    cases += 1
    if not ok:
        failures.append(name)
    print(f"{'pass' if ok else 'FAIL'}  {name}  {note}", flush=True)


def same_run(a, b):
    return a["points"] == b["points"] and a["steps"] == b["steps"]


net = os.path.join(work, "er.h5")
hmfnet("generate", "er", "--n", 20000, "--mean-degree", 40, "--seed", 3, "--output", net)
base = [net, "--K-over-Kc", "0.5,2", "--h", "0.05", "--T", "20", "--transient", "5",
        "--seed", "7", "--replicas", "3"]
for extra in (["--integrator", "yoshida4"], ["--precision", "float32"],
              ["--K-across-replicas", "--record-stride", "7"]):
    cpu = run_json("simulate", *base, *extra, "--device", "cpu")
    gpu = run_json("simulate", *base, *extra, "--device", device)
    case(f"{device} = cpu " + " ".join(extra),
         same_run(cpu, gpu) and (device == "cpu" or gpu["device"] != "cpu"),
         f"device {gpu['device']!r}, <R>_t {[round(p['R_mean'], 6) for p in gpu['points']]}")

# Checkpoints across devices: three K of 20000 steps (about a second each on either), the signal
# once the checkpoint of the second K exists.
small = os.path.join(work, "er_small.h5")
hmfnet("generate", "er", "--n", 2000, "--mean-degree", 20, "--seed", 4, "--output", small)
long_run = ["simulate", small, "--K-over-Kc", "0.5,1.5,3", "--h", "0.05", "--T", "1000",
            "--transient", "100", "--seed", "9", "--replicas", "3", "--json", "--quiet"]
whole = json.loads(hmfnet(*long_run, "--device", "cpu").stdout)
for first, second in ((device, "cpu"), ("cpu", device)):
    ckpt = os.path.join(work, f"{first}.ckpt.h5")
    if os.path.exists(ckpt):
        os.remove(ckpt)
    args = [*long_run, "--checkpoint", ckpt]
    proc = subprocess.Popen([os.path.join(cli, "run"), "hmfnet", *args, "--device", first],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    t0 = time.time()
    while not os.path.exists(ckpt) and proc.poll() is None and time.time() - t0 < 60:
        time.sleep(0.02)
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate()
    stopped = proc.returncode == 143
    resumed = json.loads(hmfnet(*args, "--resume", "--device", second).stdout)
    case(f"checkpoint {first} -> resume {second}",
         stopped and resumed["resumed"] and same_run(whole, resumed),
         f"first exit {proc.returncode} ({err.strip()[:100]})")

# Rates on one larger network (one run each; the CPU on every core of this machine).
big = os.path.join(work, "er_big.h5")
hmfnet("generate", "er", "--n", 200000, "--mean-degree", 100, "--seed", 5, "--output", big)
rate = [big, "--K-over-Kc", "2", "--h", "0.05", "--T", "6", "--transient", "1", "--seed", "1",
        "--replicas", "8", "--record-stride", "1000"]
cpu = run_json("simulate", *rate, "--device", "cpu")
gpu = run_json("simulate", *rate, "--device", device)
ratio = gpu["nnz_steps_per_second"] / cpu["nnz_steps_per_second"]
case("rate ER N=2e5 <d>=100 B=8", same_run(cpu, gpu),
     f"cpu {cpu['nnz_steps_per_second'] / 1e9:.3f} G/s ({cpu['threads']} threads), "
     f"{gpu['device']} {gpu['nnz_steps_per_second'] / 1e9:.3f} G/s: {ratio:.1f}x")
print(f"simulate: {cases} cases, {len(failures)} failed" +
      (f" ({', '.join(failures)})" if failures else ""))
sys.exit(1 if failures else 0)
