# ab_pairs.py OLD NEW VARIANT D W ROUNDS: two devstone binaries (main and a branch) run alternately,
# pinned to core 1, one warm-up pair first; prints the median (min-max) of the pairwise
# process-CPU-time ratios NEW / OLD for construction, simulation and both (docs/performance.md).
import json, subprocess, sys, statistics
old, new, v, d, w, n = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5], int(sys.argv[6])
def run(b):
    out = subprocess.run(['taskset', '-c', '1', b, '--variant', v, '--depth', d, '--width', w], capture_output=True, text=True).stdout
    j = json.loads(out.strip().splitlines()[-1]); assert j['counts_ok']
    return j['build_cpu_seconds'], j['sim_cpu_seconds']
rb, rs, rt = [], [], []
ob, nb, os_, ns = [], [], [], []
run(old); run(new)
for i in range(n):
    a = run(old); b = run(new)
    rb.append(b[0]/a[0]); rs.append(b[1]/a[1]); rt.append((b[0]+b[1])/(a[0]+a[1]))
    ob.append(a[0]); nb.append(b[0]); os_.append(a[1]); ns.append(b[1])
m = statistics.median
print(f"{v}({d},{w}) n={n} build new/old {m(rb):.2f} ({min(rb):.2f}-{max(rb):.2f})  sim {m(rs):.2f} ({min(rs):.2f}-{max(rs):.2f})  total {m(rt):.2f}  | old build {m(ob)*1e3:.1f} ms sim {m(os_)*1e3:.1f} ms, new build {m(nb)*1e3:.1f} ms sim {m(ns)*1e3:.1f} ms")
