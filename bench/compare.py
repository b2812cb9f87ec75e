#!/usr/bin/env python3
"""Side-by-side timing of yardsim and its peers (see bench/compare.sh and docs/performance.md).

Every round runs each participant once as its own process, pinned to one core and at a raised
priority, in an order that rotates from round to round (peer, yardsim, peer, yardsim ...); the
ratio yardsim / peer is taken within each round, and the table gives its median and min-max
over the rounds with each side's median. Lower ratios mean yardsim is faster.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys

DEVSTONE_CASES = [("LI", 200, 200), ("HI", 100, 100), ("HO", 100, 100), ("HOmod", 20, 20), ("HO", 200, 200)]
MB_ALGOS = ["aba", "rnea", "crba"]
MB_CASES = [("chain", 8), ("chain", 32), ("chain", 256), ("tree", 9), ("tree", 33), ("tree", 257)]


def run(cmd, pin, nice):
    """(command) => its stdout's last JSON line, the process pinned and reniced"""
    full = []
    if nice is not None:
        full += ["nice", "-n", str(nice)]
    if pin is not None:
        full += ["taskset", "-c", str(pin)]
    out = subprocess.run(full + cmd, check=True, capture_output=True, text=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def rounds(participants, n, pin, nice):
    """({name: command}) => {name: [result per round]}, order rotated each round"""
    names = list(participants)
    res = {k: [] for k in names}
    for r in range(n):
        order = names[r % len(names):] + names[:r % len(names)]
        for k in order:
            res[k].append(run(participants[k], pin, nice))
    return res


def stat(xs):
    m = statistics.median(xs)
    return m, min(xs), max(xs)


def fmt_ratio(ys, ps):
    rs = [y / p for y, p in zip(ys, ps)]
    m, lo, hi = stat(rs)
    return f"{m:.2f} ({lo:.2f}-{hi:.2f})"


def devstone(a):
    b = a.build
    print("| variant (d, w) | peer | phase | yardsim median s | peer median s | yardsim/peer median (min-max) |")
    print("|---|---|---|---|---|---|")
    for v, d, w in DEVSTONE_CASES:
        parts = {"yardsim": [f"{b}/bench/devstone/devstone", "--variant", v, "--depth", str(d), "--width", str(w)]}
        for peer in ("adevs", "cadmium"):
            exe = f"{b}/bench/peers/peer_{peer}_devstone"
            if os.path.exists(exe):
                parts[peer] = [exe, v, str(d), str(w)]
        res = rounds(parts, a.n, a.pin, a.nice)
        for k, rs in res.items():
            if not all(r["counts_ok"] for r in rs):
                sys.exit(f"compare: {k} {v}({d},{w}) counted wrong transitions")
        for peer in [k for k in res if k != "yardsim"]:
            for phase, key in (("construction", "build_{}seconds"), ("simulate", "sim_{}seconds"),
                               ("build + simulate", None)):
                for clock in ("cpu_", ""):
                    def val(r):
                        if key:
                            return r[key.format(clock)]
                        return r[f"build_{clock}seconds"] + r[f"sim_{clock}seconds"]
                    ys = [val(r) for r in res["yardsim"]]
                    ps = [val(r) for r in res[peer]]
                    label = f"{phase} ({'CPU' if clock else 'wall'})"
                    print(f"| {v}({d},{w}) | {peer} | {label} | {statistics.median(ys):.4f} | "
                          f"{statistics.median(ps):.4f} | {fmt_ratio(ys, ps)} |", flush=True)


def multibody(a):
    exe = f"{a.build}/bench/peers/peer_multibody"
    peers = [p for p in ("rbdl", "pinocchio", "pinocchio-world")
             if subprocess.run([exe, p, "aba", "chain", "1"], capture_output=True).returncode == 0]
    algos = a.algos.split(",") if a.algos else MB_ALGOS
    print("| kernel | model | N | yardsim ns | " + " | ".join(f"{p} ns | yardsim/{p}" for p in peers) + " |")
    print("|---|---|---|---|" + "---|---|" * len(peers))
    for algo in algos:
        for model, n in MB_CASES:
            parts = {"yardsim": [exe, "yardsim", algo, model, str(n)]}
            for p in peers:
                parts[p] = [exe, p, algo, model, str(n)]
            res = rounds(parts, a.n, a.pin, a.nice)
            ys = [r["ns"] for r in res["yardsim"]]
            cells = []
            for p in peers:
                ps = [r["ns"] for r in res[p]]
                cells.append(f"{statistics.median(ps):.0f} | {fmt_ratio(ys, ps)}")
            print(f"| {algo} | {model} | {n} | {statistics.median(ys):.0f} | " + " | ".join(cells) + " |", flush=True)


def instructions(cmd):
    """(command) => instructions it executes, counted by callgrind (independent of the load)"""
    out = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null"] + cmd,
                         check=True, capture_output=True, text=True).stderr
    for line in out.splitlines():
        if "refs:" in line:
            return int(line.split()[-1].replace(",", ""))
    raise RuntimeError("no callgrind count for " + " ".join(cmd))


def multibody_ir(a):
    """instructions per kernel call: (count with REPS calls - count with none) / REPS"""
    exe = f"{a.build}/bench/peers/peer_multibody"
    peers = [p for p in ("rbdl", "pinocchio", "pinocchio-world")
             if subprocess.run([exe, p, "aba", "chain", "1"], capture_output=True).returncode == 0]
    algos = a.algos.split(",") if a.algos else MB_ALGOS
    print("| kernel | model | N | yardsim instructions | " + " | ".join(f"{p} | yardsim/{p}" for p in peers) + " |")
    print("|---|---|---|---|" + "---|---|" * len(peers))
    for algo in algos:
        for model, n in MB_CASES:
            reps = max(20, 6400 // n)
            per = {}
            for lib in ["yardsim"] + peers:
                base = [exe, lib, algo, model, str(n)]
                per[lib] = (instructions(base + [str(reps)]) - instructions(base + ["0"])) / reps
            cells = [f"{per[p]:.0f} | {per['yardsim'] / per[p]:.2f}" for p in peers]
            print(f"| {algo} | {model} | {n} | {per['yardsim']:.0f} | " + " | ".join(cells) + " |", flush=True)


# (example, simulated s, extra `yardsim run` arguments): the goliath turnover as the scene has it
# (CSV and replay) and with the full JSONL trace the target names (`--trace jsonl`)
SCENES = [("goliath_turnover", 460.0, []), ("goliath_turnover", 460.0, ["--trace", "jsonl"]),
          ("floating_barge", 150.0, []), ("double_pendulum", 30.0, [])]


def scenes(a):
    """whole `yardsim run --profile` processes, pinned: real-time factor and output's share"""
    import re
    import resource
    import tempfile
    exe = f"{a.build}/cli/yardsim"
    here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    print("| scene (simulated s) | wall s | CPU s | real time x (wall) | real time x (CPU) | output share (min-max) | "
          "profile line of the median run |")
    print("|---|---|---|---|---|---|---|")
    for name, simulated, extra in SCENES:
        walls, cpus, shares, lines = [], [], [], []
        with tempfile.TemporaryDirectory() as out:
            for _ in range(a.n):
                cmd = ["nice", "-n", str(a.nice), "taskset", "-c", str(a.pin), exe, "run",
                       f"{here}/examples/{name}/scene.yaml", "-o", out, "--quiet", "--profile"] + extra
                before = resource.getrusage(resource.RUSAGE_CHILDREN)
                r = subprocess.run(cmd, check=True, capture_output=True, text=True)
                after = resource.getrusage(resource.RUSAGE_CHILDREN)
                line = [l for l in r.stderr.splitlines() if l.startswith("profile:")][-1]
                cpus.append(after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime)
                walls.append(float(re.search(r"total ([0-9.e+-]+) s", line).group(1)))
                shares.append(float(re.search(r"\(([0-9.]+) % of the run\)", line).group(1)))
                lines.append(line)
        w, c = statistics.median(walls), statistics.median(cpus)
        mid = lines[sorted(range(len(walls)), key=lambda i: walls[i])[len(walls) // 2]]
        print(f"| {' '.join([name] + extra)} ({simulated:g}) | {w:.3f} | {c:.3f} | {simulated / w:.0f} | {simulated / c:.0f} | "
              f"{statistics.median(shares):.1f} % ({min(shares):.1f}-{max(shares):.1f}) | {mid} |", flush=True)


def ode(a):
    exe = f"{a.build}/bench/multibody/bench_multibody"
    def case(name):
        return [exe, f"--benchmark_filter=^{name}/32$", "--benchmark_min_time=0.2", "--benchmark_format=json"]
    parts = {"yardsim": case("RK4Step"), "dWorldStep": case("ODEWorldStep"), "dWorldQuickStep": case("ODEQuickStep")}
    names = list(parts)
    res = {k: [] for k in names}
    for r in range(a.n):
        order = names[r % 3:] + names[:r % 3]
        for k in order:
            full = ["nice", "-n", str(a.nice), "taskset", "-c", str(a.pin)] + parts[k]
            out = json.loads(subprocess.run(full, check=True, capture_output=True, text=True).stdout)
            res[k].append(out["benchmarks"][0]["cpu_time"])
    print("| N = 32 | ODE median ns | yardsim RK4 median ns | ODE / yardsim RK4 median (min-max) |")
    print("|---|---|---|---|")
    for p in ("dWorldStep", "dWorldQuickStep"):
        rs = [o / y for o, y in zip(res[p], res["yardsim"])]
        m, lo, hi = stat(rs)
        print(f"| {p} | {statistics.median(res[p]):.0f} | {statistics.median(res['yardsim']):.0f} | "
              f"{m:.2f}x ({lo:.2f}-{hi:.2f}) |")


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("what", choices=["devstone", "multibody", "multibody-ir", "ode", "scenes"])
    ap.add_argument("--build", default="build", help="build folder configured with -DYARDSIM_PEERS_DIR")
    ap.add_argument("-n", type=int, default=7, help="rounds")
    ap.add_argument("--pin", type=int, default=1, help="core for taskset -c")
    ap.add_argument("--nice", type=int, default=-10, help="nice -n for every run (negative needs root)")
    ap.add_argument("--algos", default="", help="multibody: comma-separated subset of aba,rnea,crba")
    a = ap.parse_args()
    {"devstone": devstone, "multibody": multibody, "multibody-ir": multibody_ir, "ode": ode, "scenes": scenes}[a.what](a)


if __name__ == "__main__":
    main()
