#!/usr/bin/env python3
"""cyclecheck candidate adapter for LinuxCNC 2.9 (Debian's linuxcnc-uspace): its rs274ngc
interpreter through the `gcode` module AXIS's preview uses (full-precision canonical moves), and
the standalone `rs274 -g` for the one thing that module does not report, the lead of each
spindle-synchronized (G33) move. Both run as subprocesses, one per program, with a timeout, in a
private temporary working directory (the interpreter writes rs274ngc.var into its cwd): a
segfault, a hang or a NaN coordinate is the case's failure (the adapter exits non-zero and says
why on stderr), never a trace.

Greeting: versions 1 and 2, pipelined, `"level": "motion-alarm-presence"` — LinuxCNC emits motion
only (no pass headers) and its errors are messages, not the protocol's alarm codes.
Programs are translated by translate.py only where the dialects name the same thing.
`--plant-bug` (or CYCLECHECK_PLANT_BUG=1) moves the X of the trace's last move one increment out.
"""

import json
import math
import os
import re
import select
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from translate import Refuse, translate  # noqa: E402

PLANT_BUG = "--plant-bug" in sys.argv[1:] or os.environ.get("CYCLECHECK_PLANT_BUG") == "1"
HELLO = "cyclecheck-candidate/hello"
DECIMALS = {("metric", "isb"): 3, ("metric", "isc"): 4, ("inch", "isb"): 4, ("inch", "isc"): 5}
LIMIT_S = 5.0
RS274_TRIES = 4
PY = "/usr/bin/python3"
WORKER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "worker.py")
CANON = re.compile(r"^\s*\d+ N\S* (STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED|START_SPEED_FEED_SYNC|STOP_SPEED_FEED_SYNCH)\(([^)]*)\)")


class Failure(Exception):
    """LinuxCNC crashed, hung or produced a non-number: no trace may be answered."""


def counts(v, scale):
    v *= scale
    return int(v + 0.5) if v >= 0 else -int(-v + 0.5)


def run(cmd, cwd, what, retry_bus_error=False):
    try:
        p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=LIMIT_S)
    except subprocess.TimeoutExpired:
        raise Failure("%s hung: no result in %.0f s" % (what, LIMIT_S))
    if p.returncode < 0:
        if retry_bus_error and p.returncode == -7 and "N....." not in p.stdout:
            return None
        raise Failure("%s was killed by signal %d (%s)" % (what, -p.returncode, p.stderr.strip()[-300:]))
    return p


class Worker:
    """The gcode-module worker, kept from program to program and restarted after a failure."""

    def __init__(self, cwd):
        self.cwd, self.proc = cwd, None

    def stop(self):
        if self.proc is not None:
            self.proc.kill()
            self.proc.wait()
            self.proc = None

    def parse(self, path):
        what = "LinuxCNC's rs274ngc interpreter (gcode module)"
        if self.proc is None:
            self.proc = subprocess.Popen([PY, WORKER], cwd=self.cwd, stdin=subprocess.PIPE,
                                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
        self.proc.stdin.write(path + "\n")
        self.proc.stdin.flush()
        ready, _, _ = select.select([self.proc.stdout], [], [], LIMIT_S)
        if not ready:
            self.stop()
            raise Failure("%s hung: no result in %.0f s" % (what, LIMIT_S))
        line = self.proc.stdout.readline()
        if not line:
            status = self.proc.wait()
            self.proc = None
            if status < 0:
                raise Failure("%s was killed by signal %d" % (what, -status))
            raise Failure("%s exited with status %d" % (what, status))
        return json.loads(line)


def sync_leads(path, cwd):
    """From `rs274 -g`: one entry per canonical move, the lead (program units per revolution)
    when the move is spindle-synchronized, else None."""
    for attempt in range(RS274_TRIES):
        own = tempfile.mkdtemp(dir=cwd)  # its own rs274ngc.var, apart from the gcode module's
        try:
            # The packaged rs274 dies of SIGBUS on a few % of runs of any program, `M2` alone
            # included, before printing a canonical call (candidate.toml, [[finding]]): such a
            # run is tried again; a crash after output is the case's failure.
            p = run(["rs274", "-g", path], own, "LinuxCNC rs274", retry_bus_error=attempt + 1 < RS274_TRIES)
        finally:
            shutil.rmtree(own, ignore_errors=True)
        if p is not None:
            break
        sys.stderr.write("rs274 -g: SIGBUS before any output, tried again\n")
    out, lead = [], None
    for line in p.stdout.splitlines():
        m = CANON.match(line)
        if not m:
            continue
        name, args = m.groups()
        if name == "START_SPEED_FEED_SYNC":
            lead = float(args.split(",")[0])
        elif name == "STOP_SPEED_FEED_SYNCH":
            lead = None
        else:
            out.append(lead if name == "STRAIGHT_FEED" else None)
    return out


def expand(program, cfg, cwd, worker):
    grid = cfg["grid"]
    inch = grid["units"] == "inch"
    scale = 10 ** DECIMALS[(grid["units"], grid["increment"])]
    subs, body, line_map = translate(program, DECIMALS[(grid["units"], grid["increment"])], cfg["params"])
    pre = ["G18 G7 G90 G40 G94 %s M3 S1000" % ("G20" if inch else "G21")]
    sx, sz = cfg["start_x"], cfg["start_z"]
    if (sx, sz) != (0, 0):
        pre.append("G0 X%s Z%s" % (repr(sx / scale), repr(sz / scale)))
    lines = pre + [t for t, _ in subs] + body + ["M2"]
    origin = [0] * len(pre) + [l for _, l in subs] + line_map + [0]
    path = os.path.join(cwd, "program.ngc")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    res = worker.parse(path)
    # Only a G33 move needs its lead from rs274 -g; elsewhere no move is synchronized.
    leads = sync_leads(path, cwd) if any(re.search(r"G33\b", t) for t in body) else [None] * len(res["moves"])
    if len(leads) != len(res["moves"]):
        raise Failure("rs274 -g reported %d moves, the gcode module %d" % (len(leads), len(res["moves"])))
    to_unit = 1.0 if inch else 25.4  # the module reports inches
    lead_scale = 100_000 if inch else 10_000
    events, x, z = [], sx, sz
    for (kind, mx, mz, feed, cx, cz, rot, line), lead in zip(res["moves"], leads):
        nums = [mx, mz, feed, cx, cz]
        if any(math.isnan(v) or math.isinf(v) for v in nums):
            raise Failure("LinuxCNC produced a non-number coordinate (%r) on line %d" % (nums, origin[line - 1] if 0 < line <= len(origin) else line))
        if 0 < line <= len(origin) and line <= len(pre):
            x, z = counts(2 * mx * to_unit, scale), counts(mz * to_unit, scale)
            continue  # the unreported positioning of the start point
        ex, ez = counts(2 * mx * to_unit, scale), counts(mz * to_unit, scale)
        ev = {"event": "move", "x": ex, "z": ez, "angle": 0, "lead_change": 0}
        if kind == "arc":
            if abs(rot) != 1:
                raise Failure("LinuxCNC arc of %d turns" % rot)
            ev.update(kind="arc_cw" if rot < 0 else "arc_ccw", feed=counts(feed * to_unit, lead_scale),
                      cx=counts(2 * cx * to_unit, scale), cz=counts(cz * to_unit, scale), rule="ARC.R")
        elif kind == "rapid":
            ev.update(kind="rapid", feed=0, rule="PRJ.MODAL")
        elif lead is not None:
            ev.update(kind="thread", feed=counts(lead, lead_scale), rule="G32")
        else:
            ev.update(kind="feed", feed=counts(feed * to_unit, lead_scale), rule="PRJ.MODAL")
        if kind != "arc" and (ex, ez) == (x, z):
            continue  # PRJ.NOOP
        events.append(ev)
        x, z = ex, ez
    alarm = None
    if res["error"]:
        n = res["line"]
        line = origin[n - 1] if 0 < n <= len(origin) else 0
        sys.stderr.write("LinuxCNC error on source line %d: %s\n" % (line, res["message"]))
        alarm = {"code": "UNSUPPORTED", "number": 3003, "word": None, "rule": "PRJ.SUPPORTED", "line": line}
    if PLANT_BUG and events:
        events[-1]["x"] += 1
    return {"grid": grid, "events": events, "alarm": alarm}


def answer(req, cwd, worker):
    rid = req.get("id", 0)
    if req.get("schema") == HELLO:
        return {"id": 0, "versions": [1, 2], "pipeline": True, "level": "motion-alarm-presence"}
    if req.get("schema") not in ("cyclecheck-candidate/1", "cyclecheck-candidate/2"):
        return {"id": rid, "error": "the LinuxCNC adapter speaks versions 1 and 2 only"}
    if "program" not in req:
        return {"id": rid, "error": "LinuxCNC reads text programs: this one is not UTF-8"}
    cfg = req["config"]
    if cfg["dialect"] == "nc201":
        return {"id": rid, "error": "no translation of the nc201 dialect into LinuxCNC"}
    try:
        return {"id": rid, "trace": expand(req["program"], cfg, cwd, worker)}
    except Refuse as e:
        return {"id": rid, "error": "not translated into LinuxCNC: %s" % e}


def main():
    cwd = tempfile.mkdtemp(prefix="cyclecheck-linuxcnc-")
    worker = Worker(cwd)
    try:
        for line in sys.stdin:
            if not line.strip():
                continue
            try:
                reply = answer(json.loads(line), cwd, worker)
            except Failure as e:
                sys.stderr.write("LinuxCNC adapter: %s; no trace answered\n" % e)
                sys.stderr.flush()
                sys.exit(3)
            sys.stdout.write(json.dumps(reply, separators=(",", ":")) + "\n")
            sys.stdout.flush()
    finally:
        worker.stop()
        shutil.rmtree(cwd, ignore_errors=True)


if __name__ == "__main__":
    main()
