#!/usr/bin/env python3
"""The device check's end-to-end test of `hmfnet simulate --device cuda` (ci/device_check.sh),
with the CLI that ci/device_pack_cli.sh packed on the CPU machine:

  1. the same points (every <R>_t, SEM, energy error and momentum drift, per replica) and step
     counts as `--device cpu`, compared exactly (--json prints doubles to round-trip precision):
     float64 and float32, leapfrog and yoshida4, a K per replica (--K-across-replicas), on an ER
     network and a weighted one (the sparse force) and on K_N with and without self-loops (the
     rank-one force, 13 and 16 replicas: the CPU's AVX-512 groups whole and partial);
  2. --node-data on both forces: the results files' datasets (node data included) equal;
  3. a checkpoint written by one device and resumed on the other (SIGTERM once the checkpoint of
     the second K exists, then --resume): the points of the uninterrupted run, both ways;
  4. two MPI ranks sharing the one device (the packed launcher, D/mpirun): the points of two
     CPU ranks, on the ER network (sparse force, the ghosts through the host) and on K_N
     (rank-one force, Z summed over the ranks), and the run's note that the ranks share it;
  5. the rate of both on one larger network (stored entries x replicas x steps / s), and the
     device's name and the CPU threads beside it.

Prints one line per case (a case whose command fails is a failed case, with its error) and a
last line "simulate: N cases, M failed"; exits 1 if any failed.
Usage: device_simulate.py PACKED_CLI_DIR WORK_DIR
HMFNET_SIMULATE_DEVICE=cpu runs every case with the CPU in the device's place and
HMFNET_SIMULATE_SMALL=1 on smaller networks (ci/device_prepare.sh does both, to try the script and
the packed CLI where there is no GPU).
"""
import json
import os
import random
import signal
import subprocess
import sys
import time

cli, work = sys.argv[1], sys.argv[2]
device = os.environ.get("HMFNET_SIMULATE_DEVICE", "cuda")
small = os.environ.get("HMFNET_SIMULATE_SMALL") == "1"
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


def guarded(name, body):
    """Runs one case; an exception (a command that failed) fails it, and the others still run."""
    try:
        body()
    except Exception as e:  # noqa: BLE001 - every failure is reported as the case's
        case(name, False, f"{type(e).__name__}: {str(e)[:300]}")


def same_run(a, b):
    return a["points"] == b["points"] and a["steps"] == b["steps"]


def same_points(name, base):
    def body():
        cpu = run_json("simulate", *base, "--device", "cpu")
        gpu = run_json("simulate", *base, "--device", device)
        case(name, same_run(cpu, gpu) and (device == "cpu" or gpu["device"] != "cpu"),
             f"device {gpu['device']!r}, <R>_t {[round(p['R_mean'], 6) for p in gpu['points']]}")
    guarded(name, body)


net = os.path.join(work, "er.h5")
hmfnet("generate", "er", "--n", 2000 if small else 20000, "--mean-degree", 40, "--seed", 3,
       "--output", net)
base = [net, "--K-over-Kc", "0.5,2", "--h", "0.05", "--T", "20", "--transient", "5",
        "--seed", "7", "--replicas", "3"]
for extra in (["--integrator", "yoshida4"], ["--precision", "float32"],
              ["--K-across-replicas", "--record-stride", "7"]):
    same_points(f"ER: {device} = cpu " + " ".join(extra), base + extra)
# A weighted network (Matrix Market, real symmetric, A_nm in [0.5, 2]): the weights on the device.
weighted = os.path.join(work, "weighted.mtx")
rng = random.Random(5)
pairs = {(i, j) for i in range(1500) for j in range(i) if rng.random() < 20 / 1500}
with open(weighted, "w") as f:
    f.write(f"%%MatrixMarket matrix coordinate real symmetric\n1500 1500 {len(pairs)}\n")
    for i, j in sorted(pairs):
        f.write("%d %d %.17g\n" % (i + 1, j + 1, rng.uniform(0.5, 2.0)))
for extra in ([], ["--precision", "float32"]):
    same_points(f"weighted: {device} = cpu " + " ".join(extra),
                [weighted, "--K-over-Kc", "2", "--h", "0.05", "--T", "20", "--transient", "5",
                 "--seed", "3", "--replicas", "4", *extra])
for loops, replicas in (("--self-loops", "16"), (None, "13")):
    kn = os.path.join(work, f"k{replicas}.h5")
    hmfnet("generate", "complete", "--n", 3000, *([loops] if loops else []), "--output", kn)
    same_points(f"K_N{' ' + loops if loops else ''}: {device} = cpu, {replicas} replicas",
                [kn, "--K-over-Kc", "1.5", "--h", "0.1", "--T", "30", "--transient", "5",
                 "--seed", "2", "--replicas", replicas, "--momenta", "waterbag",
                 "--integrator", "blanes_moan", "--record-stride", "11"])



def same_files(name, base):
    """Both devices write the results file (-o); every dataset (points, node data, time series)
    equal bit for bit (the attributes hold the provenance: device, timings). h5py and numpy: the
    GPU machine's Python has both (its description in the GPU issue); without them the case fails
    naming the missing module."""
    def body():
        import h5py
        import numpy as np
        files = {}
        for role, d in (("reference", "cpu"), ("tried", device)):  # two files, even for cpu = cpu
            files[role] = os.path.join(work, f"files-{role}.h5")
            hmfnet("simulate", *base, "--device", d, "--output", files[role], "--quiet")
        names, differ = [], []
        with h5py.File(files["reference"], "r") as a, h5py.File(files["tried"], "r") as b:
            a.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
            for n in names:
                if n not in b or not np.array_equal(a[n][()], b[n][()]):
                    differ.append(n)
        node = [n for n in names if n.endswith(("R_node", "omega_node", "r_node"))]
        case(name, not differ and len(node) == 3,
             f"{len(names)} datasets, differ: {differ[:5]}")
    guarded(name, body)


# Node data (--node-data, every step's y_n read from the device): the results files equal.
same_files(f"ER --node-data: {device} = cpu",
           base[:-2] + ["--replicas", "2", "--record-stride", "10", "--node-data"])
same_files(f"K_N --node-data: {device} = cpu",
           [os.path.join(work, "k16.h5"), "--K-over-Kc", "1.5", "--h", "0.1", "--T", "20",
            "--transient", "5", "--seed", "2", "--replicas", "3", "--momenta", "waterbag",
            "--node-data"])

# Checkpoints across devices: three K of 20000 steps (about a second each on either), the signal
# once the run's first checkpoint exists (written when the second K starts, or by the 5 s timer).
small_net = os.path.join(work, "er_small.h5")
hmfnet("generate", "er", "--n", 2000, "--mean-degree", 20, "--seed", 4, "--output", small_net)
long_run = ["simulate", small_net, "--K-over-Kc", "0.5,1.5,3", "--h", "0.05",
            "--T", "200" if small else "1000", "--transient", "100", "--seed", "9",
            "--replicas", "3", "--json", "--quiet"]


uninterrupted = {}


def crossing(first, second):
    if "cpu" not in uninterrupted:
        uninterrupted["cpu"] = json.loads(hmfnet(*long_run, "--device", "cpu").stdout)
    whole = uninterrupted["cpu"]
    ckpt = os.path.join(work, f"{first}.ckpt.h5")
    if os.path.exists(ckpt):
        os.remove(ckpt)
    args = [*long_run, "--checkpoint", ckpt]
    proc = subprocess.Popen([os.path.join(cli, "run"), "hmfnet", *args, "--device", first],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    t0 = time.time()
    while not os.path.exists(ckpt) and proc.poll() is None and time.time() - t0 < 60:
        time.sleep(0.02)
    if proc.poll() is not None:
        _, err = proc.communicate()
        case(f"checkpoint {first} -> resume {second}", False,
             f"the first run ended (exit {proc.returncode}) before the signal: {err.strip()[:200]}")
        return
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate()
    resumed = json.loads(hmfnet(*args, "--resume", "--device", second).stdout)
    case(f"checkpoint {first} -> resume {second}",
         proc.returncode == 143 and resumed["resumed"] and same_run(whole, resumed),
         f"first exit {proc.returncode} ({err.strip()[:100]})")


for first, second in ((device, "cpu"), ("cpu", device)):
    guarded(f"checkpoint {first} -> resume {second}", lambda: crossing(first, second))


def rates():
    big = os.path.join(work, "er_big.h5")
    hmfnet("generate", "er", "--n", 20000 if small else 200000, "--mean-degree", 100, "--seed", 5,
           "--output", big)
    rate = [big, "--K-over-Kc", "2", "--h", "0.05", "--T", "6", "--transient", "1",
            "--seed", "1", "--replicas", "8", "--record-stride", "1000"]
    cpu = run_json("simulate", *rate, "--device", "cpu")
    gpu = run_json("simulate", *rate, "--device", device)
    ratio = gpu["nnz_steps_per_second"] / cpu["nnz_steps_per_second"]
    case("rate ER <d>=100 B=8", same_run(cpu, gpu),
         f"N = {cpu['n']}: cpu {cpu['nnz_steps_per_second'] / 1e9:.3f} G/s "
         f"({cpu['threads']} threads), {gpu['device']} "
         f"{gpu['nnz_steps_per_second'] / 1e9:.3f} G/s: {ratio:.1f}x")


def two_ranks(name, network, extra):
    """`mpirun -np 2` with --device cuda against --device cpu at 2 ranks: the same points."""
    def body():
        runs = {}
        for d in ("cpu", device):
            done = subprocess.run([os.path.join(cli, "mpirun"), "2", "hmfnet", "simulate", network,
                                   *extra, "--device", d, "--json", "--quiet"],
                                  capture_output=True, text=True)
            if done.returncode != 0:
                raise RuntimeError(f"2 ranks, --device {d}: exit {done.returncode}: "
                                   f"{done.stderr.strip()[:300]}")
            runs[d] = (json.loads(done.stdout), done.stderr)
        (cpu, _), (gpu, err) = runs["cpu"], runs[device]
        shared = device == "cpu" or "2 MPI ranks share 1 CUDA device" in err
        case(name, same_run(cpu, gpu) and cpu["ranks"] == 2 and shared,
             f"device {gpu['device']!r}, note {'seen' if shared else 'missing'}")
    guarded(name, body)


two_ranks(f"ER over 2 ranks: {device} = cpu", net, base[1:] + ["--precision", "float32"])
two_ranks(f"K_N over 2 ranks: {device} = cpu", os.path.join(work, "k13.h5"),
          ["--K-over-Kc", "1.5", "--h", "0.1", "--T", "20", "--transient", "5", "--seed", "2",
           "--replicas", "5", "--momenta", "waterbag"])
guarded("rate ER <d>=100 B=8", rates)
print(f"simulate: {cases} cases, {len(failures)} failed" +
      (f" ({', '.join(failures)})" if failures else ""))
sys.exit(1 if failures else 0)
