#!/usr/bin/env python3
"""Issue 14's mutation experiment, reproducible (docs/robustness.md, "The mutation harness").

(examples' scenes and meshes, hand-made cases, yardsim binary) => OUT/summary.md (class x outcome)
and OUT/findings/ (each finding's mutant, command and messages); exit 1 when there is a finding.
Every example file (examples/**, tests' data scenes) is mutated by class: (a) delete_key,
(b) swap_type, (c) numbers and mesh_numbers, (d) random byte mutations, (e) hand-made cases
(mutate_cases.py). A mutant is written over its file in a copy of the repository's examples, so
includes and meshes resolve; `yardsim validate` (or `sweep --dry-run`) checks the root that
reaches it (timeout 10 s); a seeded sample of the mutants that validate is run (`--until`, 30 s).
Fine: exit 0, 2 or 4, exit 1 with a located message (file:line:col). A finding: exit 3, another
status, a signal, a sanitizer report, a time-out, exit 1 without a location, "internal error",
a run that ends 0 with a non-finite number in timeseries.csv, a hand-made case's wrong status.
"""
import argparse
import collections
import concurrent.futures
import math
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mutate_cases  # noqa: E402
import mutate_classes as mc  # noqa: E402

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SOURCE_DIRS = ["examples", "tests/report/data", "tests/studies/data"]
SKIP = ["examples/custom_atomic"]  # its model type is an out-of-tree plug-in
LOC = re.compile(r"([^\s:]*[./][^\s:]*)(?::(\d+):(\d+))?: error")
SANITIZER = re.compile(r"ERROR: (Address|Leak|Memory|Thread)Sanitizer|runtime error:")
NON_FINITE = re.compile(r"^[-+]?(nan|inf|infinity)$", re.I)
FINE = ("exit 0", "exit 1 located", "exit 1 located elsewhere", "exit 2", "exit 4", "as expected")


class Mutant:
    def __init__(self, cls, src, target, kind, data, desc, line):
        self.cls, self.src, self.target, self.kind = cls, src, target, kind
        self.data, self.desc, self.line = data, desc, line


# (argv, cwd, timeout) => (status or None on time-out, stderr, seconds), the process group killed
def execute(argv, timeout, cwd=None):
    start = time.monotonic()
    p = subprocess.Popen(argv, cwd=cwd, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                         stderr=subprocess.PIPE, start_new_session=True)
    try:
        _, err = p.communicate(timeout=timeout)
        rc = p.returncode
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        _, err = p.communicate()
        rc = None
    return rc, err.decode("utf-8", "replace"), time.monotonic() - start


# (status, messages, expected statuses, location regex, mutated file and line) => outcome
def classify(rc, err, expect=None, locate=None, at=None):
    if rc is None:
        return "hang"
    if rc < 0:
        return f"signal {-rc}"
    if SANITIZER.search(err):
        return "sanitizer"
    if "internal error" in err:
        return "internal error"
    if rc not in (0, 1, 2, 4):
        return f"exit {rc}"
    if rc == 1 and not re.search(locate or LOC.pattern, err):
        return "exit 1 unlocated"
    if rc == 2 and not err.strip():
        return "exit 2 silent"
    if expect is not None:
        return "as expected" if rc in expect else f"unexpected exit {rc}"
    if rc == 1 and at is not None:
        # (the mutated file and line) => named by an error (a mesh's line inside the scene's error)
        named = re.search(r"(^|[\s/])" + re.escape(f"{at[0]}:{at[1]}:"), err, re.M)
        return "exit 1 located" if named else "exit 1 located elsewhere"
    return "exit 1 located" if rc == 1 else f"exit {rc}"


# Channels that are NaN by design: where the contact forces on a body act, without contact
# (docs/collision.md: <set>.<body>.px|py|pz)
NAN_BY_DESIGN = re.compile(r"\.p[xyz]\[m\]$")


# (timeseries.csv) => whether a data row holds nan or inf in a channel that must stay finite
def non_finite_output(path):
    if not os.path.exists(path):
        return False
    header = None
    with open(path, errors="replace") as f:
        for row in f:
            if row.startswith("#"):
                continue
            cells = [x.strip() for x in row.split(",")]
            if header is None:
                header = cells
                continue
            for i, x in enumerate(cells):
                if NON_FINITE.match(x) and not (i < len(header) and NAN_BY_DESIGN.search(header[i])):
                    return True
    return False


class Harness:
    def __init__(self, args):
        self.args = args
        self.tmp = tempfile.mkdtemp(prefix="yardsim-mutate-")
        self.master = os.path.join(self.tmp, "master")
        self.local = threading.local()
        self.workers = []
        self.lock = threading.Lock()
        for d in SOURCE_DIRS:
            shutil.copytree(os.path.join(ROOT, d), os.path.join(self.master, d),
                            ignore=shutil.ignore_patterns("*.png", "*.md", "*.py"))
        fixture = os.path.join(self.master, "examples/yard/build_fixture.sh")
        if os.path.exists(fixture):
            subprocess.run(["bash", fixture, args.binary, os.path.join(os.path.dirname(fixture), "yard.sqlite")],
                           check=True, stdout=subprocess.DEVNULL)

    # () => this thread's own copy of the examples
    def ws(self):
        if not hasattr(self.local, "ws"):
            with self.lock:
                path = os.path.join(self.tmp, f"w{len(self.workers)}")
                self.workers.append(path)
            shutil.copytree(self.master, path, symlinks=True)
            self.local.ws = path
        return self.local.ws

    def command(self, kind, target, ws, out):
        path = os.path.join(ws, target)
        if kind == "sweep":
            return [self.args.binary, "sweep", path, "--dry-run", "-o", out, "--quiet"]
        if kind == "run":  # (--until) => never longer than the scene's own end (andrews: 0.03 s at 5 us)
            until = min(self.args.until, self.untils.get(target, math.inf))
            return [self.args.binary, "run", path, "-o", out, "--quiet", "--until", repr(until)]
        return [self.args.binary, "validate", path]

    # (mutant, validate or run) => (outcome, status, messages, seconds, command)
    def try_mutant(self, m, phase):
        ws = self.ws()
        path = os.path.join(ws, m.src)
        with open(path, "rb") as f:
            original = f.read()
        out = os.path.join(ws, "out")
        shutil.rmtree(out, ignore_errors=True)
        try:
            with open(path, "wb") as f:
                f.write(m.data)
            kind = m.kind if phase == "validate" else "run"
            argv = self.command(kind, m.target, ws, out)
            timeout = self.args.validate_timeout if phase == "validate" else self.args.run_timeout
            rc, err, secs = execute(argv, timeout)
            at = (os.path.basename(m.src), m.line) if m.line else None
            outcome = classify(rc, err, at=at)
            if phase == "run" and rc == 0 and non_finite_output(os.path.join(out, "timeseries.csv")):
                outcome = "non-finite output"
            return outcome, rc, err, secs, [a.replace(ws, "WS") for a in argv]
        finally:
            with open(path, "wb") as f:
                f.write(original)
            shutil.rmtree(out, ignore_errors=True)

    # (hand-made case) => (outcome, status, messages, seconds, command)
    def try_case(self, case):
        name, files, argv, expect, locate = case
        ws = self.ws()
        d = os.path.join(ws, "hand", name)
        out = os.path.join(ws, "hand_out", name)
        os.makedirs(d, exist_ok=True)
        try:
            for fname, content in files.items():
                p = os.path.join(d, fname)
                if content is mutate_cases.FIFO:
                    os.mkfifo(p)
                else:
                    with open(p, "wb") as f:
                        f.write(content if isinstance(content, bytes) else content.encode())
            full = [self.args.binary] + [a.format(d=d, o=out, ws=ws) for a in argv]
            rc, err, secs = execute(full, self.args.run_timeout)
            return classify(rc, err, expect, locate), rc, err, secs, [a.replace(ws, "WS") for a in full]
        finally:
            shutil.rmtree(d, ignore_errors=True)
            shutil.rmtree(out, ignore_errors=True)

    # () => the example files, each with its kind, and the roots that validate as they are
    def baseline(self):
        files = []
        for d in SOURCE_DIRS:
            for base, _, names in os.walk(os.path.join(self.master, d)):
                for n in names:
                    rel = os.path.relpath(os.path.join(base, n), self.master)
                    if n.lower().endswith((".yaml", ".obj", ".stl")) and not any(rel.startswith(s) for s in SKIP):
                        files.append(rel)
        files.sort()
        kinds, roots, self.untils = {}, [], {}
        for rel in files:
            if not rel.endswith(".yaml"):
                continue
            with open(os.path.join(self.master, rel)) as f:
                root = mc.compose(f.read())
            kind = "sweep" if root is not None and any(
                getattr(k, "value", None) == "sweep" for k, _ in getattr(root, "value", [])) else "validate"
            kinds[rel] = kind
            for k, v in getattr(root, "value", []) if isinstance(getattr(root, "value", None), list) else []:
                if getattr(k, "value", None) == "until" and mc.is_number(v):
                    self.untils[rel] = float(v.value)
            rc, _, _ = execute(self.command(kind, rel, self.master, os.path.join(self.tmp, "base", rel)), 60)
            if rc == 0:
                roots.append(rel)
        return files, kinds, roots

    # (files, roots) => for each file the first root whose includes and meshes reach it
    def targets(self, files, roots):
        refs = {}
        for rel in files:
            if rel.endswith(".yaml"):
                with open(os.path.join(self.master, rel), errors="replace") as f:
                    text = f.read()
                names = re.findall(r"[\w./-]+\.(?:yaml|obj|stl|csv)", text, re.I)
                refs[rel] = {os.path.normpath(os.path.join(os.path.dirname(rel), n)) for n in names} & set(files)
        targets = {}
        for root in roots:
            seen, todo = set(), [root]
            while todo:
                f = todo.pop()
                if f not in seen:
                    seen.add(f)
                    todo.extend(refs.get(f, ()))
            for f in sorted(seen, key=lambda f: f != root):
                targets.setdefault(f, root)
        return targets

    def generate(self, files, kinds, targets):
        rng = random.Random(self.args.seed)
        mutants = []
        for rel in files:
            if rel not in targets:
                continue
            target = targets[rel]
            kind = kinds.get(target, "validate")
            with open(os.path.join(self.master, rel), "rb") as f:
                data = f.read()
            gens = []
            if rel.endswith(".yaml"):
                text = data.decode()
                gens = [("delete_key", mc.delete_key(text)), ("swap_type", mc.swap_type(text)),
                        ("numbers", mc.numbers(text))]
            else:
                gens = [("mesh_numbers", mc.mesh_numbers(data.decode(errors="replace"), rng, self.args.mesh_numbers))]
            gens.append(("random", mc.random_bytes(data, rng, self.args.random)))
            for cls, gen in gens:
                for desc, make, line in gen:
                    mutants.append(Mutant(cls, rel, target, kind, make, desc, line))
        self.generated = collections.Counter(m.cls for m in mutants)
        if self.args.sample:
            by = collections.defaultdict(list)
            for m in mutants:
                by[m.cls].append(m)
            mutants = [m for ms in by.values() for m in rng.sample(ms, min(self.args.sample, len(ms)))]
        for m in mutants:  # (make) => the mutant's bytes, built for those kept only
            data = m.data()
            m.data = data if isinstance(data, bytes) else data.encode()
        return mutants

    # (function, items) => its results in order, on --jobs threads, a line every 500
    def pool(self, fn, items):
        done = [0]

        def counted(item):
            r = fn(item)
            with self.lock:
                done[0] += 1
                if done[0] % 500 == 0:
                    print(f"mutate: {done[0]} of {len(items)}", flush=True)
            return r

        with concurrent.futures.ThreadPoolExecutor(self.args.jobs) as ex:
            return list(ex.map(counted, items))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--binary", default=os.path.join(ROOT, "build/cli/yardsim"))
    p.add_argument("--out", default="out/mutate", help="output folder (summary.md, findings/)")
    p.add_argument("--random", type=int, default=100, help="random byte mutants per file")
    p.add_argument("--mesh-numbers", type=int, default=20, help="numbers sampled per mesh for class (c)")
    p.add_argument("--sample", type=int, default=0, help="at most this many validates per class (0: all)")
    p.add_argument("--runs", type=int, default=300, help="runs of a seeded sample of mutants that validate")
    p.add_argument("--until", type=float, default=2.0, help="--until of those runs, s")
    p.add_argument("--seed", type=int, default=14)
    p.add_argument("--jobs", type=int, default=1)
    p.add_argument("--validate-timeout", type=float, default=10.0)
    p.add_argument("--run-timeout", type=float, default=30.0)
    p.add_argument("--no-hand", action="store_true", help="leave out the hand-made cases")
    args = p.parse_args()
    args.binary = os.path.abspath(args.binary)
    start = time.monotonic()
    h = Harness(args)
    try:
        files, kinds, roots = h.baseline()
        targets = h.targets(files, roots)
        print(f"mutate: copy and baseline {time.monotonic() - start:.0f} s", flush=True)
        mutants = h.generate(files, kinds, targets)
        print(f"mutate: {len(mutants)} mutants of {len(targets)} files ({len(roots)} roots), "
              f"{time.monotonic() - start:.0f} s", flush=True)
        results = [("validate", m) + r for m, r in zip(mutants, h.pool(lambda m: h.try_mutant(m, "validate"), mutants))]
        valid = [m for m, r in zip(mutants, results) if r[2] == "exit 0" and m.kind == "validate"]
        sample = random.Random(args.seed).sample(valid, min(args.runs, len(valid)))
        print(f"mutate: validated, {time.monotonic() - start:.0f} s", flush=True)
        results += [("run", m) + r for m, r in zip(sample, h.pool(lambda m: h.try_mutant(m, "run"), sample))]
        print(f"mutate: runs done, {time.monotonic() - start:.0f} s", flush=True)
        if not args.no_hand:
            with open(os.path.join(ROOT, "tests/report/data/over_mbl.yaml")) as f:
                cases = mutate_cases.hand_cases(f.read())
            results += [("hand", c) + r for c, r in zip(cases, h.pool(h.try_case, cases))]
        findings = write_report(args, results, time.monotonic() - start, sorted(set(files) - set(targets)),
                                h.generated)
    finally:
        shutil.rmtree(h.tmp, ignore_errors=True)
    return 1 if findings else 0


# (results) => OUT/summary.md and OUT/findings/; the number of findings
def write_report(args, results, seconds, skipped, generated):
    shutil.rmtree(os.path.join(args.out, "findings"), ignore_errors=True)
    os.makedirs(os.path.join(args.out, "findings"), exist_ok=True)
    table = collections.defaultdict(collections.Counter)
    lines, n = [], 0
    for phase, item, outcome, rc, err, secs, argv in results:
        cls = "hand" if phase == "hand" else f"{phase}: {item.cls}"
        table[cls][outcome] += 1
        if outcome in FINE:
            continue
        n += 1
        folder = os.path.join(args.out, "findings", f"{n:04d}")
        os.makedirs(folder)
        what = item[0] if phase == "hand" else f"{item.src}: {item.desc}"
        if phase != "hand":
            with open(os.path.join(folder, os.path.basename(item.src)), "wb") as f:
                f.write(item.data)
        with open(os.path.join(folder, "finding.txt"), "w") as f:
            f.write(f"class: {cls}\noutcome: {outcome} (status {rc}, {secs:.2f} s)\ninput: {what}\n"
                    f"command: {' '.join(argv)}\n(WS: a copy of examples/, tests/report/data, tests/studies/data; "
                    f"the mutant replaces the file of its name)\n\n{err[:4000]}")
        lines.append(f"- {folder}: {cls}, {outcome}: {what[:160]}")
    outcomes = sorted({o for c in table.values() for o in c}, key=lambda o: (o not in FINE, o))
    with open(os.path.join(args.out, "summary.md"), "w") as f:
        f.write(f"# yardsim mutation experiment\n\nseed {args.seed}, {args.random} random mutants per file, "
                f"sample {args.sample or 'all'}, {args.runs} runs (--until {args.until}), binary {args.binary}; "
                f"{sum(sum(c.values()) for c in table.values())} inputs in {seconds:.0f} s; {n} finding(s)\n\n")
        f.write("| class | generated | inputs | " + " | ".join(outcomes) + " |\n|---|---|---|" + "---|" * len(outcomes) + "\n")
        for cls in sorted(table):
            gen = generated.get(cls.split(": ")[-1], "") if cls.startswith("validate") else ""
            f.write(f"| {cls} | {gen} | {sum(table[cls].values())} | "
                    + " | ".join(str(table[cls][o]) for o in outcomes) + " |\n")
        f.write("\nFiles no root reaches (not mutated): " + (", ".join(skipped) or "none") + "\n")
        f.write("\n## Findings\n\n" + ("\n".join(lines) or "none") + "\n")
    with open(os.path.join(args.out, "summary.md")) as f:
        sys.stdout.write(f.read().split("## Findings")[0])
    print(f"mutate: {n} finding(s); {args.out}/summary.md")
    return n


if __name__ == "__main__":
    sys.exit(main())
