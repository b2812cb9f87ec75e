"""(e) The hand-made cases of issue 14's experiment: every defect the issue lists, and the CLI's
arguments as inputs (docs/robustness.md, "The mutation harness").

A case is (name, files, argv, expect, locate): the files are written into a fresh folder D
(bytes, text, or FIFO for a named pipe); argv is the yardsim command after the binary, with {d}
for D, {o} for an output folder, {ws} for the copy of the repository's examples; expect the exit
statuses that are right; locate a regex the messages must contain (default file:line:col).
"""
import random

FIFO = object()
NESTED_BOMB = "".join(f"l{i}: &l{i} [" + ", ".join([f"*l{i - 1}"] * 10) + "]\n" for i in range(1, 13))


# (over_mbl.yaml's text) => the cases
def hand_cases(base):
    def scene(extra_components="", old=None, new=None, tail=""):
        text = base.replace(old, new, 1) if old else base
        if extra_components:
            text = text.replace("components:\n", "components:\n" + extra_components, 1)
        return text + tail

    actor = "  {n}: {{type: wire_actor, params: {{rope: hoist, payout: 1.0, speed: 0.25, accel: 0.5, {rule}}}}}\n"
    run = ["run", "{d}/scene.yaml", "-o", "{o}", "--quiet"]
    val = ["validate", "{d}/scene.yaml"]
    S = {"scene.yaml": base}
    cases = [
        # start rules
        ("after_all_self", {"scene.yaml": scene(actor.format(n="a2", rule="after_all: [a2]"))}, val, {1}, None),
        ("after_cycle", {"scene.yaml": scene(actor.format(n="a2", rule="after_all: [a3]")
                                             + actor.format(n="a3", rule="after_any: [a2]"))}, val, {1}, None),
        ("after_unknown", {"scene.yaml": scene(actor.format(n="a2", rule="after_all: [a9]"))}, val, {1}, None),
        # YAML documents, aliases, structure
        ("second_document", {"scene.yaml": scene(tail="---\nname: two\n")}, val, {1}, None),
        ("alias_bomb", {"scene.yaml": scene(tail="l0: &l0 [lol]\n" + NESTED_BOMB)}, val, {1}, None),
        ("alias_self", {"scene.yaml": scene(tail="x: &a [1, *a]\n")}, val, {1}, None),
        ("alias_undefined", {"scene.yaml": scene(tail="x: *nothing\n")}, val, {1}, None),
        ("duplicate_key", {"scene.yaml": scene(tail="until: 1\n")}, val, {1}, None),
        ("deep_nesting", {"scene.yaml": scene(tail="x: " + "[" * 100000 + "]" * 100000 + "\n")}, val, {1}, None),
        ("long_key", {"scene.yaml": scene(tail="k" * 1000000 + ": 1\n")}, val, {1}, None),
        ("tab_indent", {"scene.yaml": scene(old="  interval: 0.01", new="\tinterval: 0.01")}, val, {1}, None),
        ("complex_key", {"scene.yaml": scene(tail="? [a, b]\n: 1\n")}, val, {1}, None),
        ("null_key", {"scene.yaml": scene(tail="~: 1\n")}, val, {1}, None),
        ("bom", {"scene.yaml": "\ufeff" + base}, val, {0, 1}, None),
        ("crlf", {"scene.yaml": base.replace("\n", "\r\n")}, val, {0}, None),
        ("empty_file", {"scene.yaml": ""}, val, {1}, None),
        ("scalar_root", {"scene.yaml": "42\n"}, val, {1}, None),
        ("list_root", {"scene.yaml": "- a\n- b\n"}, val, {1}, None),
        ("binary", {"scene.yaml": random.Random(14).randbytes(4096)}, val, {1}, None),
        ("huge_file", {"scene.yaml": base + ("#" * 1023 + "\n") * (17 * 1024)}, val, {1}, None),
        # files that are no regular files, includes
        ("validate_dev_zero", {}, ["validate", "/dev/zero"], {1}, r"/dev/zero"),
        ("validate_dev_urandom", {}, ["validate", "/dev/urandom"], {1}, r"/dev/urandom"),
        ("validate_folder", {}, ["validate", "{d}"], {1}, r"not a regular file|folder|directory"),
        ("validate_fifo", {"fifo.yaml": FIFO}, ["validate", "{d}/fifo.yaml"], {1}, r"fifo"),
        ("validate_missing", {}, ["validate", "{d}/missing.yaml"], {1}, r"missing\.yaml"),
        ("include_dev_zero", {"scene.yaml": scene("  z: {include: /dev/zero}\n")}, val, {1}, None),
        ("include_dev_urandom", {"scene.yaml": scene("  z: {include: /dev/urandom}\n")}, val, {1}, None),
        ("include_fifo", {"scene.yaml": scene("  z: {include: fifo.yaml}\n"), "fifo.yaml": FIFO}, val, {1}, None),
        ("include_self", {"scene.yaml": scene("  z: {include: scene.yaml}\n")}, val, {1}, None),
        ("include_cycle", {"scene.yaml": scene("  z: {include: a.yaml}\n"),
                           "a.yaml": "schema_version: 1\ncomponents:\n  b: {include: b.yaml}\n",
                           "b.yaml": "schema_version: 1\ncomponents:\n  a: {include: a.yaml}\n"}, val, {1}, None),
        ("include_missing", {"scene.yaml": scene("  z: {include: nothing.yaml}\n")}, val, {1}, None),
        ("include_folder", {"scene.yaml": scene("  z: {include: .}\n")}, val, {1}, None),
        ("include_long_name", {"scene.yaml": scene("  z: {include: " + "n" * 5000 + ".yaml}\n")}, val, {1}, None),
        ("mesh_dev_zero", {"scene.yaml": scene(old="geometry: {box: [3, 2, 1.5]}",
                                               new="geometry: {mesh: /dev/zero}")}, val, {1}, None),
        ("mesh_missing", {"scene.yaml": scene(old="geometry: {box: [3, 2, 1.5]}",
                                              new="geometry: {mesh: none.obj}")}, val, {1}, None),
        ("mesh_huge", {"scene.yaml": scene(old="geometry: {box: [3, 2, 1.5]}", new="geometry: {mesh: big.obj}"),
                       "big.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n" + ("#" * 1023 + "\n") * (17 * 1024)},
         val, {0, 1}, None),
        # values the issue lists
        ("parts_2_5", {"scene.yaml": scene(old="      mbl: 147150.0", new="      mbl: 147150.0\n      parts: 2.5")},
         val, {1}, None),
        ("static_misspelt", {"scene.yaml": scene(old="static: {hoist.tension:", new="static: {hoist.tensoin:")},
         run, {1}, None),
        ("static_nan", {"scene.yaml": scene(old="static: {hoist.tension: 98100.0", new="static: {hoist.tension: .nan")},
         val, {1}, None),
        ("watch_unknown", {"scene.yaml": scene(old="channel: lift.q", new="channel: lift.qq")}, run, {1}, None),
        ("record_interval_tiny", {"scene.yaml": scene(old="interval: 0.01", new="interval: 1.0e-6")}, val, {1}, None),
        ("dt_tiny", {"scene.yaml": scene(old="dt: 0.001", new="dt: 1.0e-300")}, val, {1}, None),
        # the command line
        ("until_negative", S, run + ["--until", "-5"], {1}, r"--until"),
        ("until_nan", S, run + ["--until", "nan"], {1}, r"--until"),
        ("until_inf", S, run + ["--until", "inf"], {1}, r"--until"),
        ("until_huge", S, run + ["--until", "1e300"], {1}, r"until"),
        ("until_text", S, run + ["--until", "abc"], {1}, r"--until"),
        ("until_empty", S, run + ["--until", ""], {1}, r"--until"),
        ("until_zero", S, run + ["--until", "0"], {0}, r"."),
        ("checkpoint_negative", S, run + ["--checkpoint-every", "-1"], {1}, r"--checkpoint-every"),
        ("checkpoint_tiny", S, run + ["--checkpoint-every", "1e-300"], {1}, r"checkpoint"),
        ("checkpoint_zero", S, run + ["--checkpoint-every", "0"], {0, 1}, r"checkpoint"),
        ("transitions_zero", S, run + ["--max-transitions-per-instant", "0"], {1}, r"--max-transitions"),
        ("format_bogus", S, run + ["--format", "xml"], {1}, r"--format"),
        ("trace_bogus", S, run + ["--trace", "bogus"], {1}, r"trace"),
        ("fail_on_bogus", S, run + ["--fail-on", "x"], {1}, r"--fail-on"),
        ("fail_on_alarm", S, run + ["--fail-on", "alarm"], {4}, r"."),
        ("outdir_empty", S, ["run", "{d}/scene.yaml", "-o", "", "--quiet"], {1}, r"-o"),
        ("outdir_under_file", S, ["run", "{d}/scene.yaml", "-o", "{d}/scene.yaml/out", "--quiet"], {1}, r"-o"),
        ("outdir_proc", S, ["run", "{d}/scene.yaml", "-o", "/proc/yardsim_out", "--quiet"], {1}, r"-o"),
        ("restart_missing", S, run + ["--restart", "{d}/none.ckpt"], {1}, r"none\.ckpt"),
        ("restart_garbage", {"scene.yaml": base, "bad.ckpt": "garbage\n"}, run + ["--restart", "{d}/bad.ckpt"],
         {1}, r"bad\.ckpt"),
        ("restart_dev_zero", S, run + ["--restart", "/dev/zero"], {1}, r"/dev/zero"),
        ("wp_repeats_negative", {}, ["wp", "{ws}/examples/stiff/slack_snap.yaml", "-o", "{o}", "--repeats", "-1"],
         {1}, r"--repeats"),
        ("wp_repeats_zero", {}, ["wp", "{ws}/examples/stiff/slack_snap.yaml", "-o", "{o}", "--repeats", "0"],
         {1}, r"--repeats"),
        ("wp_repeats_fraction", {}, ["wp", "{ws}/examples/stiff/slack_snap.yaml", "-o", "{o}", "--repeats", "2.5"],
         {1}, r"--repeats"),
        ("wp_no_block", S, ["wp", "{d}/scene.yaml", "-o", "{o}"], {1}, r"wp"),
        ("command_bogus", {}, ["bogus"], {1}, r"unknown command 'bogus'"),
        ("command_none", {}, [], {1}, r"command"),
        ("run_no_scene", {}, ["run"], {1}, r"scene"),
        ("trace_missing", {}, ["trace", "{d}/none.jsonl"], {1}, r"none\.jsonl"),
        ("trace_garbage", {"t.jsonl": "{not json\n"}, ["trace", "{d}/t.jsonl"], {0, 1}, r"t\.jsonl"),
        ("trace_dev_zero", {}, ["trace", "/dev/zero"], {1}, r"/dev/zero"),
        ("trace_bad_record", {"t.jsonl": '{"t": "abc", "model": "a", "kind": "out"}\n'}, ["trace", "{d}/t.jsonl"],
         {1}, r"t\.jsonl:1"),
        ("trace_from_nan", {"t.jsonl": ""}, ["trace", "{d}/t.jsonl", "--from", "nan"], {1}, r"--from"),
        ("report_missing", {}, ["report", "{d}/none"], {1}, r"none"),
        ("report_empty_folder", {"x.txt": ""}, ["report", "{d}"], {1}, r"timeseries\.csv|run\.json"),
        ("report_bad_number", {"timeseries.csv": "# yardsim\ntime[s],a[m]\n0,abc\n"}, ["report", "{d}"], {1},
         r"timeseries\.csv:\d+"),
        ("list_channels_dev_zero", {}, ["list-channels", "/dev/zero"], {1}, r"/dev/zero"),
        ("sweep_missing", {}, ["sweep", "{d}/none.yaml", "-o", "{o}", "--dry-run"], {1}, r"none\.yaml"),
        ("sweep_jobs_zero", {}, ["sweep", "{ws}/examples/sweeps/barge_operability/sweep.yaml", "-o", "{o}", "-j", "0",
                                 "--dry-run"], {1}, r"-j|--jobs"),
        ("sweep_dev_zero", {}, ["sweep", "/dev/zero", "-o", "{o}", "--dry-run"], {1}, r"/dev/zero"),
    ]
    return cases
