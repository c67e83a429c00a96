"""Runs LinuxCNC's rs274ngc interpreter (the `gcode` module AXIS's preview uses) on files and
prints each one's canonical motion as one JSON line, at full precision: [kind, x_radius, z,
feed, cx, cz, rot, line] per move (inches, as the module reports them), then the result code
and message. It reads one path per line on stdin; the adapter restarts it when it dies."""
import json
import os
import sys

import gcode


class Canon:
    def __init__(self):
        self.moves, self.feed, self.line = [], 0.0, 0
        self.parameter_file = ""

    def __getattr__(self, name):
        if name.startswith("__"):
            raise AttributeError(name)
        return lambda *a: None

    def next_line(self, st):
        self.line = st.sequence_number

    def get_external_length_units(self): return 1.0
    def get_external_angular_units(self): return 1.0
    def get_axis_mask(self): return 7  # X Y Z, as the standalone rs274
    def get_block_delete(self): return False
    def check_abort(self): return False
    def get_tool(self, n): return (n, 0., 0., 0., 0., 0., 0., 0., 0., 0., 0., 0., 0., 0)
    def set_feed_rate(self, f): self.feed = f

    def straight_traverse(self, x, y, z, *rest):
        self.moves.append(["rapid", x, z, 0.0, 0.0, 0.0, 0, self.line])

    def straight_feed(self, x, y, z, *rest):
        self.moves.append(["feed", x, z, self.feed, 0.0, 0.0, 0, self.line])

    def arc_feed(self, first_end, second_end, first_c, second_c, rot, *rest):
        # XZ plane (G18): first axis Z, second X.
        self.moves.append(["arc", second_end, first_end, self.feed, second_c, first_c, rot, self.line])


def parse(path):
    for stale in ("rs274ngc.var", "rs274ngc.var.bak"):
        if os.path.exists(stale):
            os.remove(stale)  # no state carried from one program to the next
    canon = Canon()
    result, seq = gcode.parse(path, canon, "", "")
    msg = gcode.strerror(result) if result > gcode.MIN_ERROR else ""
    return {"moves": canon.moves, "result": result, "error": result > gcode.MIN_ERROR,
            "line": seq, "message": msg}


for line in sys.stdin:
    sys.stdout.write(json.dumps(parse(line.rstrip("\n"))) + "\n")
    sys.stdout.flush()
