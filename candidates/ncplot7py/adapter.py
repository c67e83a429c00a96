#!/usr/bin/env python3
"""cyclecheck candidate adapter for ncplot7py 0.2.0 (PyPI, LGPL-3.0), FANUC_TURN control.

Speaks docs/CANDIDATE.md (version 1: thread cycles, G00/G01) and drives ncplot7py in-process
through `NCExecutionEngine.get_Syncro_plot`, one fresh control per request. The trace is what
ncplot7py's toolpath says: the end point of every motion segment (X radius doubled to a diameter,
rounded to the grid), its traversal (rapid, feed, thread), and the lead the threading cycle used
(recorded from ncplot7py's own threading emitter). ncplot7py emits no pass headers, so the
greeting declares `"level": "motion-alarm-presence"`: only moves are compared, and an alarm only
by its presence (ncplot7py's error numbers do not map one to one onto the protocol's codes).

Refused (`{"id","error"}`), because ncplot7py 0.2.0 cannot be told them: the `nc201` dialect,
G76 under `gsk` (its G76 is FANUC's two-block format), G76 programs off the metric ISB grid (its
G76 P/Q/R integers are fixed at 0.001 mm), No.19 != 0 and No.107 != 0 (its G92 has no pull-out),
subprograms (M98/M99: it has none and runs past an M98), and programs that are not UTF-8. ncplot7py's errors become an alarm. A block with axis words that
ncplot7py executed without motion and without an error (a silent drop, e.g. `G0092`) is never
answered as a trace: the adapter exits with status 3 and says why on stderr (a `crash` failure).

`--plant-bug` (or CYCLECHECK_PLANT_BUG=1) moves the X of the trace's last move one increment
out: a deliberate error for candidates/plant_bug_check.py.
"""

import contextlib
import json
import re
import os
import sys

PLANT_BUG = "--plant-bug" in sys.argv[1:] or os.environ.get("CYCLECHECK_PLANT_BUG") == "1"
HELLO = "cyclecheck-candidate/hello"
SCHEMA = "cyclecheck-candidate/1"
VERSION = "0.2.0"
DECIMALS = {("metric", "isb"): 3, ("metric", "isc"): 4, ("inch", "isb"): 4, ("inch", "isc"): 5}
AXES = {"X", "U", "Z", "W"}

# ncplot7py error numbers and what the alarm says (code, word, rule) — indicative only: the
# level is motion-alarm-presence, the code is not compared.
ERRORS = {
    -2: ("DUPLICATE_WORD", "PRJ.WORD"), 923: ("WORD_NOT_ALLOWED", "PRJ.WORD"),
    760: ("WORD_NOT_ALLOWED", "F76.FORMAT"), 764: ("WORD_NOT_ALLOWED", "F76.FORMAT"),
    924: ("MISSING_WORD", "G92.FORMAT"), 765: ("MISSING_WORD", "G76.REQUIRED"),
    762: ("OUT_OF_RANGE", "F76.FORMAT"), 767: ("OUT_OF_RANGE", "G76.DEPTH.LAST"),
    769: ("NOT_INTEGER", "COM.RANGES"), 761: ("NOT_INTEGER", "COM.RANGES"),
    770: ("OUT_OF_RANGE", "COM.RANGES"), 920: ("OUT_OF_RANGE", "COM.RANGES"),
    922: ("OUT_OF_RANGE", "COM.RANGES"), 763: ("MISSING_WORD", "G76.FORMAT"),
}
NUMBERS = {"DUPLICATE_WORD": 1004, "WORD_NOT_ALLOWED": 1005, "UNSUPPORTED_CODE": 1007,
           "MISSING_WORD": 2001, "OUT_OF_RANGE": 2002, "NOT_INTEGER": 2004, "UNSUPPORTED": 3003}


class SilentDrop(Exception):
    """ncplot7py executed a block with axis words, moved nothing and reported no error."""


def load_ncplot():
    """Imports ncplot7py and wraps its threading emitter so that each thread segment's lead is
    recorded as ncplot7py used it (its toolpath carries no feed)."""
    with contextlib.redirect_stdout(sys.stderr):
        from ncplot7py.application.nc_execution import NCExecutionEngine
        from ncplot7py.domain.cnc_state import CNCState
        from ncplot7py.domain.machines import get_machine_config
        from ncplot7py.domain.handlers.fanuc_turn_cnc import threading_primitives as tp
        from ncplot7py.domain.handlers import motion
        from ncplot7py.infrastructure.machines.base_stateful_control import UniversalConfigDrivenControl
    leads = []
    feeds = []
    inside = []
    emit = tp.ThreadingPrimitiveEmitter._emit

    def recording_emit(self, node, state, *, geometry, traversal, source_code, lead):
        before = len(self.segments)
        inside.append(True)
        try:
            out = emit(self, node, state, geometry=geometry, traversal=traversal, source_code=source_code, lead=lead)
        finally:
            inside.pop()
        if len(self.segments) > before and traversal == "FEED":
            leads.append(lead)
        return out

    tp.ThreadingPrimitiveEmitter._emit = recording_emit
    linear = motion.MotionHandler._linear_interpolate

    def recording_linear(self, start, resolved, state, rapid=False, *a, **k):
        out = linear(self, start, resolved, state, rapid, *a, **k)
        if not rapid and not inside:
            feeds.append(state.feed_rate)
        return out

    motion.MotionHandler._linear_interpolate = recording_linear

    def run(program):
        leads.clear()
        feeds.clear()
        state = CNCState(machine_config=get_machine_config("FANUC_TURN"))
        # One plot point per move: ncplot7py's own override of its 0.5 mm interpolation step
        # (the end points, all a trace carries, do not depend on it).
        state.extra["max_segment"] = 1e9
        control = UniversalConfigDrivenControl(init_nc_states=[state])
        engine = NCExecutionEngine(control)
        with contextlib.redirect_stdout(sys.stderr):
            result = engine.get_Syncro_plot([program], synch=False)
        canal = getattr(control, "_canals", {}).get(1)
        nodes = list(getattr(canal, "_exec_sequence", []))
        return result, list(engine.errors), list(leads), list(feeds), nodes

    return run


def counts(value, scale):
    """A float length or lead as an integer count, rounded half away from zero."""
    v = value * scale
    return int(v + 0.5) if v >= 0 else -int(-v + 0.5)


def axis_lines(program):
    """1-based line numbers of the lines that write an axis word (X U Z W), comments aside."""
    out = set()
    for n, line in enumerate(program.split("\n"), start=1):
        depth, text = 0, []
        for ch in line:
            if ch == "(":
                depth += 1
            elif ch == ")" and depth:
                depth -= 1
            elif depth == 0:
                text.append(ch)
        t = "".join(text)
        if any(c in AXES for c in t):
            out.add(n)
    return out


def refusal(program, cfg):
    """Why ncplot7py cannot serve this request, or None."""
    if cfg["dialect"] == "nc201":
        return "ncplot7py 0.2.0 has no nc201 dialect (it is a FANUC control)"
    params = cfg["params"]
    text = program.upper().replace(" ", "")
    if re.search(r"M0*9[89](?![0-9.])", text):
        return "ncplot7py 0.2.0 has no subprograms (M98/M99): it runs past an M98 without calling"
    if "G92" in text and params.get("no19_pullout", 0) != 0:
        return "ncplot7py 0.2.0 has no G92 pull-out (thread chamfer): only No.19 = 0 can be served"
    if "G92" in text and params.get("no107_pullout_speed", 0) != 0:
        return "ncplot7py 0.2.0 has no G92 pull-out speed (No.107)"
    if "G76" in text:
        if cfg["dialect"] != "fanuc":
            return "ncplot7py 0.2.0 implements only FANUC's two-block G76, not the gsk G76"
        if (cfg["grid"]["units"], cfg["grid"]["increment"]) != ("metric", "isb"):
            return "ncplot7py 0.2.0 reads G76 P/Q/R integers as 0.001 mm: only the metric ISB grid"
    return None


def trace_of(run, program, cfg):
    grid = cfg["grid"]
    inch = grid["units"] == "inch"
    scale = 10 ** DECIMALS[(grid["units"], grid["increment"])]
    lead_scale = 100_000 if inch else 10_000
    unit = 25.4 if inch else 1.0  # ncplot7py works in mm after G20
    sx, sz = cfg["start_x"] / scale, cfg["start_z"] / scale
    # The preamble stands on line 1 before the program's first line (';' keeps line numbers):
    # inch mode, spindle on (its thread cycles need a speed), and the start point by a rapid
    # that is not reported (the reference starts there without moving).
    pre = ["G20"] if inch else []
    pre.append("S1000 M3")
    positioned = (sx, sz) != (0.0, 0.0)
    if positioned:
        pre.append("G0 X%r Z%r" % (sx, sz))
    result, errors, leads, feeds, nodes = run(";".join(pre) + ";" + program)
    plot = []
    for canal in result:
        if isinstance(canal, dict):
            plot = [p for p in canal.get("plot", []) if p.get("geometry")]
    if positioned and plot:
        plot = plot[1:]  # the unreported positioning rapid
    events = []
    x, z = cfg["start_x"], cfg["start_z"]
    moved_lines = set()
    for p in plot:
        moved_lines.add(p.get("lineNumber"))
        geometry, traversal, source = p["geometry"], p["traversal"], p["sourceCode"]
        if geometry != "LINEAR":
            raise SilentDrop("ncplot7py emitted a %s segment, which this adapter does not map" % geometry)
        ex = counts(2 * p["x"][-1] / unit, scale)
        ez = counts(p["z"][-1] / unit, scale)
        if traversal == "RAPID":
            kind, feed, rule = "rapid", 0, "PRJ.MODAL"
        elif source in ("G92", "G76"):
            kind, feed, rule = "thread", counts(leads.pop(0) / unit, lead_scale), source + ".PATH"
        else:
            kind, feed, rule = "feed", counts(feeds.pop(0) / unit, lead_scale), "PRJ.MODAL"
        if (ex, ez) == (x, z):
            continue  # PRJ.NOOP: ncplot7py plots zero-length segments
        events.append({"event": "move", "kind": kind, "x": ex, "z": ez, "feed": feed, "angle": 0,
                       "lead_change": 0, "rule": rule})
        x, z = ex, ez
    alarm = None
    if errors:
        e = errors[0]
        code, rule = ERRORS.get(e.get("code"), ("UNSUPPORTED", "PRJ.SUPPORTED"))
        word = (e.get("value") or "")[:1].upper()
        alarm = {"code": code, "number": NUMBERS[code], "word": word if word.isalpha() else None,
                 "rule": rule, "line": int(e.get("line") or 0)}
        sys.stderr.write("ncplot7py error %s at line %s: %s\n" % (e.get("code"), e.get("line"), e.get("message")))
    else:
        executed = {getattr(n, "nc_code_line_nr", None) for n in nodes}
        dropped = sorted(l for l in axis_lines(program) & executed if l not in moved_lines)
        if dropped:
            raise SilentDrop("ncplot7py executed line %d, which writes an axis word, without motion "
                             "and without an error" % dropped[0])
    if PLANT_BUG and events:
        events[-1]["x"] += 1
    return {"grid": grid, "events": events, "alarm": alarm}


def answer(run, req):
    rid = req.get("id", 0)
    if req.get("schema") == HELLO:
        return {"id": 0, "versions": [1], "pipeline": True, "level": "motion-alarm-presence"}
    if req.get("schema") != SCHEMA:
        return {"id": rid, "error": "ncplot7py adapter speaks %s only, not %s" % (SCHEMA, req.get("schema"))}
    if "program" not in req:
        return {"id": rid, "error": "ncplot7py takes text programs: this one is not UTF-8"}
    program, cfg = req["program"], req["config"]
    why = refusal(program, cfg)
    if why:
        return {"id": rid, "error": why}
    return {"id": rid, "trace": trace_of(run, program, cfg)}


def main():
    run = load_ncplot()
    out = sys.stdout
    for line in sys.stdin:
        if not line.strip():
            continue
        try:
            reply = answer(run, json.loads(line))
        except SilentDrop as e:
            sys.stderr.write("ncplot7py adapter: %s; refusing to answer an incomplete trace\n" % e)
            sys.stderr.flush()
            sys.exit(3)
        out.write(json.dumps(reply, separators=(",", ":")) + "\n")
        out.flush()


if __name__ == "__main__":
    main()
