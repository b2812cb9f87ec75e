#!/usr/bin/env python3
"""The sweep tests' independent reader of sweep.h5 (h5py, no yardsim code).

  sweep_h5_dump.py FILE table        => the case table, one CSV line per case: id, the varied
                                        params, status, the collected scalars (repr, 17 digits)
  sweep_h5_dump.py FILE series ID    => /cases/ID/: one line per sample: time and every channel
"""
import sys

import h5py


def num(x):
    return repr(float(x))


def main():
    path, what = sys.argv[1], sys.argv[2]
    with h5py.File(path, "r") as f:
        t = f["table"]
        if what == "table":
            params = list(t["params"].keys())
            collected = list(t["collected"].keys())
            print(",".join(["id"] + params + ["status"] + collected))
            status = t["status"].asstr()[:]
            for i, case in enumerate(t["id"][:]):
                cells = [str(int(case))] + [num(t["params"][p][i]) for p in params] + [status[i]]
                cells += [num(t["collected"][c][i]) for c in collected]
                print(",".join(cells))
        else:
            g = f["cases"][sys.argv[3]]
            names = ["time"] + sorted(k for k in g.keys() if k != "time")
            print(",".join(names))
            for k in range(len(g["time"])):
                print(",".join(num(g[n][k]) for n in names))


main()
