#!/usr/bin/env python3
"""The planted one-increment error must be reported as a divergence, never absorbed.

For a candidate NAME (ncplot7py, linuxcnc) and its programs candidates/NAME/plant/*.nc (named
FAMILY_*.nc: g92_, f76_ run under the fanuc dialect when f76, g32_ …):
1. each program conforms with the adapter as it is (`cyclecheck diff --candidate`), else the
   check is void and fails;
2. with CYCLECHECK_PLANT_BUG=1 (the adapter moves the X of the trace's last move one increment
   out) each program diverges, on field x, and no declaration of candidates/NAME/deviations.toml
   matches that divergence (rule, family, field — the rule `certify --deviations` applies).
Prints one line per program and `N passed, M failed`; exit 1 on any failure.

    candidates/plant_bug_check.py ncplot7py [--cyclecheck target/release/cyclecheck]
"""

import glob
import json
import os
import subprocess
import sys
import tomllib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def diff(cyclecheck, name, program, planted):
    family = os.path.basename(program).split("_")[0]
    cmd = [cyclecheck, "diff", "--format", "json", "--param", "19=0",
           "--dialect", "fanuc" if family == "f76" else "gsk",
           "--candidate", "candidates/%s/run" % name, program]
    env = dict(os.environ)
    env.pop("CYCLECHECK_PLANT_BUG", None)
    if planted:
        env["CYCLECHECK_PLANT_BUG"] = "1"
    p = subprocess.run(cmd, cwd=ROOT, env=env, capture_output=True, text=True, timeout=300)
    if not p.stdout.strip():
        raise RuntimeError("cyclecheck diff printed nothing (exit %d): %s" % (p.returncode, p.stderr[-500:]))
    return family, json.loads(p.stdout.strip().splitlines()[-1])


def absorbed_by(deviations, family, div):
    """The declaration that would absorb the divergence, as `certify --deviations` matches."""
    for d in deviations:
        if d["rule"] != div.get("rule"):
            continue
        if d.get("family") not in (None, family):
            continue
        if d.get("field") not in (None, div.get("field")):
            continue
        return d
    return None


def main():
    args = sys.argv[1:]
    if not args:
        sys.exit(__doc__)
    name = args[0]
    cyclecheck = args[args.index("--cyclecheck") + 1] if "--cyclecheck" in args else "target/release/cyclecheck"
    with open(os.path.join(ROOT, "candidates", name, "deviations.toml"), "rb") as f:
        deviations = tomllib.load(f).get("deviation", [])
    programs = sorted(glob.glob(os.path.join(ROOT, "candidates", name, "plant", "*.nc")))
    passed = failed = 0
    for program in programs:
        rel = os.path.relpath(program, ROOT)
        family, plain = diff(cyclecheck, name, rel, planted=False)
        _, bug = diff(cyclecheck, name, rel, planted=True)
        div = bug.get("divergence") or {}
        if not plain.get("conform"):
            verdict = "FAIL (void: the program does not conform without the planted bug: %s)" % json.dumps(plain)[:300]
        elif bug.get("conform") or not div:
            verdict = "FAIL (the planted bug was not reported: %s)" % json.dumps(bug)[:300]
        elif div.get("field") != "x":
            verdict = "FAIL (the planted bug is on x, the divergence names %r)" % div.get("field")
        elif absorbed_by(deviations, family, div):
            verdict = "FAIL (absorbed by the declared deviation %r)" % absorbed_by(deviations, family, div)
        else:
            verdict = "ok (diverges at event %s, field x, rule %s: %s vs %s; no declaration matches)" % (
                div.get("index"), div.get("rule"), div.get("values", {}).get("reference"),
                div.get("values", {}).get("candidate"))
        ok = verdict.startswith("ok")
        passed += ok
        failed += not ok
        print("%s %s: %s" % (name, rel, verdict))
    if not programs:
        print("%s: no programs under candidates/%s/plant" % (name, name))
        failed += 1
    print("%d passed, %d failed" % (passed, failed))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
