#!/usr/bin/env python3
"""An example candidate expander for `cyclecheck`, in Python 3 (standard library only).

It speaks the candidate protocol `cyclecheck-candidate/1` (docs/CANDIDATE.md): one JSON request
per line on stdin, one JSON response per line on stdout. It answers the greeting
(`cyclecheck-candidate/hello`) with version 1 and `"pipeline": true`, so cyclecheck sends it no
later version and reports those cases as refused; it still refuses a request of any other
version, as a version-1 candidate should. `--legacy` makes it refuse the greeting too, as every
candidate written before the greeting does: it is then sent every version, one request at a
time, and refuses the others case by case. It is an independent implementation of
the G92 single thread cycle (M002) and of the program rules a G92 program needs, written from
docs/RULES.md and docs/INTERPRETATION.md: the lexer (PRJ.LEX, PRJ.WORD), the modal interpreter
(PRJ.MODAL, PRJ.SUPPORTED, COM.ABSINC, COM.LEAD), word values and ranges (COM.UNITS, COM.RANGES),
G00/G01 moves, and every G92.* rule: the path (step ③ refused when it would run toward the part),
taper, the J/K pull-out table (No.5131 for JK.1), multi-start, inch, and the alarms a G92 program
can raise; the spindle codes (G50 S, G96, G97: G50.SMAX, G96.SMAX, G96.RAPID) and subprograms
(M98, M99: SUB.CALL, SUB.FIND, SUB.RETURN, SUB.NEST), which the campaign's programs use. The second block of a G76/G78 cycle is outside its scope:
it answers with an error for such programs (run it with `cyclecheck certify --cycles g92`).

    cyclecheck certify --cycles g92 --candidate 'python3 examples/g92_candidate.py'
    cyclecheck certify --cycles g92 --candidate 'python3 examples/g92_candidate.py --legacy'

`--plant-bug` plants a deliberate bug for the harness's own test: the end X of every G92
pull-out on a Z-long thread is one increment further out than the rule gives (G92.PULLOUT).
"""

import json
import sys

SCHEMA = "cyclecheck-candidate/1"
HELLO = "cyclecheck-candidate/hello"
PLANT_BUG = "--plant-bug" in sys.argv[1:]
LEGACY = "--legacy" in sys.argv[1:]

N = 999_999_999  # the largest length, increments (COM.RANGES)
JK_MAX = 99_999_999  # G92 J, K
ALWAYS = "MNOST"  # words every block accepts (N, O, M, S, T)

# Alarm codes: name -> number (PRJ.TRACE alarm form).
CODES = {
    "BAD_CHARACTER": 1001, "BAD_NUMBER": 1002, "UNCLOSED_COMMENT": 1003, "DUPLICATE_WORD": 1004,
    "WORD_NOT_ALLOWED": 1005, "CONFLICT": 1006, "UNSUPPORTED_CODE": 1007, "MISSING_WORD": 2001,
    "OUT_OF_RANGE": 2002, "PRECISION": 2003, "NOT_INTEGER": 2004, "BLOCK_NOT_FOUND": 2005,
    "GEOMETRY": 3001, "TOO_MANY_PASSES": 3002, "UNSUPPORTED": 3003, "NESTING": 3006,
}

FANUC_ANGLES = (80, 60, 55, 40, 30, 29, 0)  # FANUC G76 tool angles (F76.FORMAT, PRJ.DIALECT)
MAX_RPM = 99_999  # G50 S (G50.SMAX)
SUB_LEVELS = 4  # SUB.NEST


class Alarm(Exception):
    """An alarm ends the expansion: code, word (a byte value or None), rule, line."""

    def __init__(self, code, word, rule, line):
        super().__init__(code)
        self.code, self.word, self.rule, self.line = code, word, rule, line

    def json(self):
        if self.word is None:
            word = None
        elif 0x21 <= self.word <= 0x7E:
            word = chr(self.word)
        else:
            word = "0x%02X" % self.word
        return {"code": self.code, "number": CODES[self.code], "word": word, "rule": self.rule, "line": self.line}


class OutOfScope(Exception):
    """A program this candidate does not implement (answered as a protocol error)."""


def alarm(code, letter, rule, line):
    return Alarm(code, ord(letter) if isinstance(letter, str) else letter, rule, line)


def half_up(num, den):
    """round(num / den), half away from zero, exactly (den > 0)."""
    q = (2 * abs(num) + den) // (2 * den)
    return -q if num < 0 else q


def sign(v):
    return (v > 0) - (v < 0)


_TAN = {}


def round_mul_tan_degrees(c, degrees):
    """round(c·tan(degrees°)) for c ≥ 0 and whole degrees 1…89 (G76.PULLOUT's tangent), in
    fixed point with 60 decimal digits: far finer than any tie but 45° (tan = 1, exact here)."""
    if degrees == 45:
        return c
    scale = 10 ** 60
    if degrees not in _TAN:
        def arctan_inv(x):
            total = term = scale // x
            n, s = 1, 1
            while term:
                term //= x * x
                n += 2
                s = -s
                total += s * (term // n)
            return total
        pi = 4 * (4 * arctan_inv(5) - arctan_inv(239))
        theta = pi * degrees // 180
        sin, cos = 0, 0
        term, k = theta, 1
        while term:
            sin += term
            term = -term * theta // scale * theta // scale // ((k + 1) * (k + 2))
            k += 2
        term, k = scale, 0
        while term:
            cos += term
            term = -term * theta // scale * theta // scale // ((k + 1) * (k + 2))
            k += 2
        _TAN[degrees] = sin * scale // cos
    return (c * _TAN[degrees] + scale // 2) // scale


# ----------------------------------------------------------------------------------------------
# Numbers as written

class Number:
    __slots__ = ("negative", "mantissa", "decimals", "point")

    def __init__(self):
        self.negative, self.mantissa, self.decimals, self.point = False, 0, 0, False

    def scaled(self, places):
        """An exact count of 10^-places, or 'precision' / 'overflow'."""
        m = self.mantissa
        if self.decimals > places:
            cut = 10 ** (self.decimals - places)
            if m % cut:
                return "precision"
            m //= cut
        else:
            shift = places - self.decimals
            if shift > 30:
                return 0 if m == 0 else "overflow"
            m *= 10 ** shift
            if m >= 2 ** 128:
                return "overflow"
        if m > 2 ** 63 - 1:
            return "overflow"
        return -m if self.negative else m

    def integer(self):
        return "not_integer" if self.point else self.scaled(0)


# ----------------------------------------------------------------------------------------------
# Lexer (PRJ.LEX, PRJ.WORD)

class Block:
    def __init__(self, line):
        self.line = line
        self.words = {}  # letter -> Number
        self.g = []  # G words in order

    def has(self, letter):
        return letter in self.words

    def letters(self):
        return sorted(self.words)


def blocks(src):
    """Yields the blocks of a program; raises the first lexical alarm where it occurs. A UTF-8
    byte-order mark at the very start is skipped (PRJ.LEX)."""
    pos, line, n = 0, 1, len(src)
    if src.startswith(b"\xef\xbb\xbf"):
        pos = 3

    def number(letter):
        nonlocal pos
        while pos < n and src[pos] in b" \t\r%":
            pos += 1
        num = Number()
        if pos < n and src[pos] in b"+-":
            num.negative = src[pos] == ord("-")
            pos += 1
        digits = significant = 0
        while pos < n:
            b = src[pos]
            if 0x30 <= b <= 0x39:
                digits += 1
                if significant or b != 0x30:
                    significant += 1
                if significant > 18 or (num.point and num.decimals >= 18):
                    raise alarm("BAD_NUMBER", letter, "PRJ.LEX", line)
                num.mantissa = num.mantissa * 10 + (b - 0x30)
                if num.point:
                    num.decimals += 1
            elif b == 0x2E and not num.point:
                num.point = True
            else:
                break
            pos += 1
        if digits == 0:
            raise alarm("BAD_NUMBER", letter, "PRJ.LEX", line)
        if num.mantissa == 0:
            num.negative = False
        return num

    while True:
        block = None
        while True:
            while pos < n and src[pos] in b" \t\r%":
                pos += 1
            if pos >= n:
                if block is not None:
                    yield block
                return
            b = src[pos]
            if b in b"\n;":
                pos += 1
                if b == 0x0A:
                    line += 1
                if block is not None:
                    break
            elif b == 0x28:  # '(' comment, closed on its line
                opened = line
                pos += 1
                while True:
                    if pos >= n:
                        raise alarm("UNCLOSED_COMMENT", "(", "PRJ.LEX", opened)
                    c = src[pos]
                    pos += 1
                    if c == 0x29:
                        break
                    if c == 0x0A:
                        raise alarm("UNCLOSED_COMMENT", "(", "PRJ.LEX", opened)
            elif (0x41 <= b <= 0x5A) or (0x61 <= b <= 0x7A):
                letter = chr(b).upper()
                word_line = line
                pos += 1
                value = number(letter)
                if block is None:
                    block = Block(word_line)
                if letter == "G":
                    if len(block.g) == 4:
                        raise alarm("DUPLICATE_WORD", "G", "PRJ.WORD", word_line)
                    block.g.append(value)
                elif letter in block.words:
                    raise alarm("DUPLICATE_WORD", letter, "PRJ.WORD", word_line)
                else:
                    block.words[letter] = value
            else:
                raise alarm("BAD_CHARACTER", b, "PRJ.LEX", line)
        yield block


# ----------------------------------------------------------------------------------------------
# Configuration

def decimals(grid):
    return {("metric", "isb"): 3, ("metric", "isc"): 4, ("inch", "isb"): 4, ("inch", "isc"): 5}[
        (grid["units"], grid["increment"])]


def lead_decimals(grid):
    return 4 if grid["units"] == "metric" else 5


def check_config(cfg):
    """The configuration's ranges, before the first block (alarms on line 0)."""
    p = cfg["params"]

    def within(v, lo, hi, word, rule):
        if not lo <= v <= hi:
            raise Alarm("OUT_OF_RANGE", word, rule, 0)

    within(cfg["start_x"], -N, N, ord("X"), "COM.RANGES")
    within(cfg["start_z"], -N, N, ord("Z"), "COM.RANGES")
    for key, lo, hi, rule in [
        ("no19_pullout", 0, 255, "G92.JK.1"), ("no107_pullout_speed", 0, 999_999, "G92.JK.8"),
        ("no18_bit6_hold", 0, 1, "G92.HOLD"), ("p5130_chamfer", 0, 99, "G76.PULLOUT"),
        ("p5131_chamfer_angle", 1, 89, "G76.PULLOUT"), ("p5140_min_cut", 0, N, "G76.DEFAULTS"),
        ("p5141_finish_allowance", 0, N, "G76.DEFAULTS"), ("p5142_finish_passes", 1, 99, "G76.DEFAULTS"),
        ("p5143_tool_angle", 0, 99, "G76.DEFAULTS"), ("p5144_infeed_mode", 0, 4, "G78.MODE"),
        ("p5145_depth_mode", 0, 1, "G78.DEPTHMODE"), ("max_passes", 1, 1_000_000, "PRJ.MAXPASS"),
    ]:
        within(p[key], lo, hi, None, rule)
    if cfg["dialect"] == "fanuc" and p["p5143_tool_angle"] not in FANUC_ANGLES:
        raise Alarm("OUT_OF_RANGE", None, "F76.FORMAT", 0)


# ----------------------------------------------------------------------------------------------
# Word values (COM.UNITS, COM.RANGES, COM.LEAD)

def number_alarm(err, letter, line):
    if err == "precision":
        return alarm("PRECISION", letter, "COM.UNITS", line)
    if err == "not_integer":
        return alarm("NOT_INTEGER", letter, "COM.RANGES", line)
    return alarm("OUT_OF_RANGE", letter, "COM.RANGES", line)


def in_range(v, lo, hi, letter, rule, line):
    if isinstance(v, str):
        raise number_alarm(v, letter, line)
    if not lo <= v <= hi:
        raise alarm("OUT_OF_RANGE", letter, rule, line)
    return v


def length(num, letter, grid, lo, hi, line):
    return in_range(num.scaled(decimals(grid)), lo, hi, letter, "COM.RANGES", line)


def integer(num, letter, lo, hi, rule, line):
    return in_range(num.integer(), lo, hi, letter, rule, line)


def micron(num, letter, cfg, lo, hi, line):
    """G76 P(k), Q(Δd), Q(Δdmin): least increments when written without a point under fanuc."""
    if cfg["dialect"] == "fanuc" and not num.point:
        return integer(num, letter, lo, hi, "COM.RANGES", line)
    return length(num, letter, cfg["grid"], lo, hi, line)


def lead_from_f(num, grid, line):
    top = 99_990_000 if grid["units"] == "metric" else 999_000
    return in_range(num.scaled(lead_decimals(grid)), 1, top, "F", "COM.RANGES", line)


def lead_from_i(num, grid, line):
    metric = grid["units"] == "metric"
    i4 = in_range(num.scaled(4), 1, 2_540_000 if metric else 1_000_000, "I", "COM.RANGES", line)
    return half_up(2_540_000_000 if metric else 1_000_000_000, i4)


def check_p_digits(cycle, p, dialect, line):
    """P(m)(r)(a) of a G76/G78 first block: m ≥ 1, G78 mode ≤ 4, FANUC tool angles."""
    m, mid, a = p // 10_000, (p // 100) % 100, p % 100
    if m == 0:
        raise alarm("OUT_OF_RANGE", "P", "G76.FINISH", line)
    if cycle == "G78" and mid > 4:
        raise alarm("OUT_OF_RANGE", "P", "G78.MODE", line)
    if dialect == "fanuc" and a not in FANUC_ANGLES:
        raise alarm("OUT_OF_RANGE", "P", "F76.FORMAT", line)


# ----------------------------------------------------------------------------------------------
# The machine (PRJ.MODAL)

MOTION_CODES = (0, 1, 92, 76, 78)


class Machine:
    def __init__(self, cfg):
        self.cfg = cfg
        self.grid = cfg["grid"]
        self.params = cfg["params"]
        self.x, self.z = cfg["start_x"], cfg["start_z"]
        self.events = []
        self.motion = "G00"
        self.feed = None
        self.j = self.k = None
        self.l = 1
        self.run_reset()
        # Spindle (G50.SMAX, G96.SPEED): G96 in force, the maximum set, a G96.SMAX alarm due.
        self.surface = False
        self.smax = None
        self.due = None
        self.in_subprogram = False

    def run_reset(self):
        self.run_x = self.run_z = None
        self.run_r = 0
        self.run_index = 0

    # Trace (PRJ.TRACE, PRJ.NOOP)
    def move(self, kind, x, z, feed, angle, rule):
        if x == self.x and z == self.z:
            return
        self.events.append({"event": "move", "kind": kind, "x": x, "z": z, "feed": feed, "angle": angle,
                            "lead_change": 0, "lead_change_angle": 0, "lead_floor": 0, "rule": rule})
        self.x, self.z = x, z

    def rapid(self, x, z, rule):
        self.move("rapid", x, z, 0, 0, rule)

    def thread(self, x, z, lead, angle, rule):
        self.move("thread", x, z, lead, angle, rule)

    def block(self, b):
        """Executes one block: "next", "end" (M02, M30), "return" (M99), or ("call", n, runs,
        line) for M98 (SUB.CALL)."""
        line = b.line
        fanuc = self.cfg["dialect"] == "fanuc"
        # G and M codes (PRJ.SUPPORTED, PRJ.DIALECT, COM.UNITS)
        code = None
        for g in b.g:
            if g.point or g.negative:
                raise alarm("UNSUPPORTED_CODE", "G", "PRJ.SUPPORTED", line)
            m = g.mantissa
            if m == 78 and fanuc:
                raise alarm("UNSUPPORTED_CODE", "G", "PRJ.DIALECT", line)
            if m in MOTION_CODES:
                code = code if code is not None else m
            elif m in (20, 21):
                if ("inch" if m == 20 else "metric") != self.grid["units"]:
                    raise alarm("UNSUPPORTED", "G", "COM.UNITS", line)
            elif m == 50 and any(b.has(a) for a in "XUZW"):
                # G50 X Z (the work coordinates, G50.COORD) is outside this example's scope.
                raise alarm("UNSUPPORTED_CODE", "G", "PRJ.SUPPORTED", line)
            elif m not in (18, 40, 50, 96, 97, 99):
                # G50 S (the spindle maximum), G96/G97 (surface speed, rpm): no motion (G50.SMAX).
                raise alarm("UNSUPPORTED_CODE", "G", "PRJ.SUPPORTED", line)
        end = sub = False
        if b.has("M"):
            mw = b.words["M"]
            if mw.point:
                raise alarm("NOT_INTEGER", "M", "COM.RANGES", line)
            if mw.negative or mw.mantissa > 99:
                raise alarm("UNSUPPORTED_CODE", "M", "PRJ.SUPPORTED", line)
            end = mw.mantissa in (2, 30)
            if mw.mantissa == 99 and not self.in_subprogram:
                # SUB.RETURN: M99 in the main program would restart it endlessly.
                raise alarm("UNSUPPORTED", "M", "SUB.RETURN", line)
            sub = mw.mantissa in (98, 99)
        # Conflicts (PRJ.WORD, COM.ABSINC, COM.LEAD)
        if sum(1 for g in b.g if not g.point and not g.negative and g.mantissa in MOTION_CODES) > 1:
            raise alarm("CONFLICT", "G", "PRJ.WORD", line)
        for a, c, rule in (("X", "U", "COM.ABSINC"), ("Z", "W", "COM.ABSINC"), ("F", "I", "COM.LEAD")):
            if b.has(a) and b.has(c):
                raise alarm("CONFLICT", c, rule, line)
        if sub:
            return self.sub_block(b)
        # The kind of block
        axes = any(b.has(a) for a in "XUZW")
        if code is None:
            code = {"G00": 0, "G01": 1, "G92": 92}[self.motion]
            written92 = False
        else:
            written92 = code == 92
        if code in (76, 78):
            kind = ("second" if axes else "first", "G76" if code == 76 else "G78")
        else:
            kind = (code, None)
        # Words allowed (PRJ.WORD, F76.FORMAT), alphabetical
        if kind[0] in (0, 1):
            own = gsk = "XUZWF"
        elif kind[0] == 92:
            own = gsk = "XUZWRFIJKL"
        elif kind[0] == "first":
            gsk = "PQRDLE"
            own = "PQR" if fanuc and kind[1] == "G76" else gsk
        else:
            gsk = "XUZWRPQJKFI"
            own = "XUZWRPQFI" if fanuc and kind[1] == "G76" else gsk
        for letter in b.letters():
            if letter in ALWAYS or letter in own:
                continue
            raise alarm("WORD_NOT_ALLOWED", letter, "F76.FORMAT" if letter in gsk else "PRJ.WORD", line)
        # Values, alphabetical
        v = {}
        g50 = any(g.mantissa == 50 for g in b.g)
        for letter in b.letters():
            if letter == "S":
                v["S"] = self.s_value(b.words["S"], g50, line)
                continue
            if letter in ALWAYS:
                continue
            num = b.words[letter]
            if letter in "XUZW":
                v[letter] = length(num, letter, self.grid, -N, N, line)
            elif letter == "F":
                v[letter] = lead_from_f(num, self.grid, line)
            elif letter == "I":
                v[letter] = lead_from_i(num, self.grid, line)
            elif kind[0] == 92:
                if letter == "R":
                    v[letter] = length(num, letter, self.grid, -N, N, line)
                elif letter in "JK":
                    v[letter] = length(num, letter, self.grid, -JK_MAX, JK_MAX, line)
                else:  # L
                    v[letter] = integer(num, letter, 1, 99, "COM.RANGES", line)
            elif kind[0] == "first":
                if letter == "P":
                    v[letter] = integer(num, letter, 0, 999_999, "COM.RANGES", line)
                    check_p_digits(kind[1], v[letter], self.cfg["dialect"], line)
                elif letter == "Q":
                    v[letter] = micron(num, letter, self.cfg, 0, N, line)
                elif letter in "RE":
                    v[letter] = length(num, letter, self.grid, 0, N, line)
                elif letter == "D":
                    top, rule = (2, "G76.MODE") if kind[1] == "G76" else (1, "G78.DEPTHMODE")
                    v[letter] = integer(num, letter, 0, top, rule, line)
                else:  # L
                    v[letter] = integer(num, letter, 1, 999, "COM.RANGES", line)
            else:  # a second block
                if letter == "R":
                    v[letter] = length(num, letter, self.grid, -N, N, line)
                elif letter in "PQ":
                    v[letter] = micron(num, letter, self.cfg, 1, N, line)
                else:  # J, K
                    v[letter] = length(num, letter, self.grid, 0, N, line)
        self.spindle(b, v, g50)
        # Execution
        if kind[0] in (0, 1):
            self.linear(kind[0] == 1, axes, v, line)
        elif kind[0] == 92:
            self.g92(written92, axes, v, line)
        elif kind[0] == "second":
            raise OutOfScope("the second block of %s is not implemented by this candidate (G92 only)" % kind[1])
        # A first block only stores its words for a later second block: no motion.
        self.missing_words_checked()
        return "end" if end else "next"

    def s_value(self, num, g50, line):
        """S: an integer; with G50 in the block the maximum, 1 … 99 999 (G50.SMAX)."""
        v = num.integer()
        if v == "not_integer":
            raise alarm("NOT_INTEGER", "S", "COM.RANGES", line)
        if g50:
            if v == "overflow" or not 1 <= v <= MAX_RPM:
                raise alarm("OUT_OF_RANGE", "S", "G50.SMAX", line)
        elif v == "overflow":
            raise alarm("OUT_OF_RANGE", "S", "COM.RANGES", line)
        return v

    def spindle(self, b, v, g50):
        """G96/G97 take effect in their block; S is the maximum with G50, else a surface speed
        under G96 or an rpm under G97. A G96 with no maximum from an earlier block is due as
        MISSING WORD S (G96.SMAX) at the end of the block's step 4."""
        g96 = any(g.mantissa == 96 for g in b.g)
        self.due = alarm("MISSING_WORD", "S", "G96.SMAX", b.line) if g96 and self.smax is None else None
        for g in b.g:
            if g.mantissa in (96, 97):
                self.surface = g.mantissa == 96
        if "S" in v and g50:
            self.smax = v["S"]

    def missing_words_checked(self):
        """The end of check step 4: a G96.SMAX alarm due is raised here."""
        due, self.due = self.due, None
        if due is not None:
            raise due

    def sub_block(self, b):
        """An M98 block takes N, M, P (SUB.CALL), an M99 block N, M (SUB.RETURN); no state."""
        call = b.words["M"].mantissa == 98
        allowed, rule = ("MNP", "SUB.CALL") if call else ("MN", "SUB.RETURN")
        letters = sorted(set(b.letters()) | ({"G"} if b.g else set()))
        for letter in letters:
            if letter not in allowed:
                raise alarm("WORD_NOT_ALLOWED", letter, rule, b.line)
        if not call:
            return "return"
        if not b.has("P"):
            raise alarm("MISSING_WORD", "P", "SUB.CALL", b.line)
        p = b.words["P"].integer()
        if p == "not_integer":
            raise alarm("NOT_INTEGER", "P", "COM.RANGES", b.line)
        if p == "overflow" or not 1 <= p <= 99_999_999 or p % 10_000 == 0:
            raise alarm("OUT_OF_RANGE", "P", "SUB.CALL", b.line)
        return ("call", p % 10_000, max(p // 10_000, 1), b.line)

    def take_lead(self, v):
        f = v.get("F", v.get("I"))
        if f is not None:
            self.feed = f

    def end_point(self, v):
        x = v["X"] if "X" in v else (self.x + v["U"] if "U" in v else None)
        z = v["Z"] if "Z" in v else (self.z + v["W"] if "W" in v else None)
        return x, z

    def linear(self, feed_move, axes, v, line):
        """G00 / G01: one move, both axes together, at the modal feed for G01."""
        self.take_lead(v)
        if feed_move and axes and self.feed is None:
            raise alarm("MISSING_WORD", "F", "COM.LEAD", line)
        self.missing_words_checked()
        # G96.RAPID (the letter, g96.rapid = refuse): no program block moves at rapid under G96.
        refuse = self.cfg.get("readings", {}).get("g96.rapid", "refuse") == "refuse"
        if not feed_move and axes and self.surface and refuse:
            raise alarm("UNSUPPORTED", "G", "G96.RAPID", line)
        self.motion = "G01" if feed_move else "G00"
        if not axes:
            return
        x, z = self.end_point(v)
        x = self.x if x is None else x
        z = self.z if z is None else z
        if feed_move:
            self.move("feed", x, z, self.feed, 0, "PRJ.MODAL")
        else:
            self.rapid(x, z, "PRJ.MODAL")

    def g92(self, written, axes, v, line):
        """G92.MODAL: a run of cycles; J, K, L, F kept for the program, end X, Z and R for the run."""
        if written and self.motion != "G92":
            self.run_reset()
        self.motion = "G92"
        self.take_lead(v)
        if "J" in v:
            self.j = v["J"]
        if "K" in v:
            self.k = v["K"]
        if "L" in v:
            self.l = v["L"]
        if "R" in v:
            self.run_r = v["R"]
        if not axes:
            return
        if self.feed is None:
            raise alarm("MISSING_WORD", "F", "COM.LEAD", line)
        self.missing_words_checked()
        ax, az = self.x, self.z
        x, z = self.end_point(v)
        dx = x if x is not None else (self.run_x if self.run_x is not None else ax)
        dz = z if z is not None else (self.run_z if self.run_z is not None else az)
        self.run_x, self.run_z = dx, dz
        self.run_index += 1
        self.g92_cycle(ax, az, dx, dz, line)

    def g92_cycle(self, ax, az, dx, dz, line):
        r, lead, starts = self.run_r, self.feed, self.l
        w = dz - az
        if w == 0:  # G92.FORMAT: a face thread
            raise alarm("GEOMETRY", "Z", "G92.FORMAT", line)
        u = dx - ax
        if r != 0 and u != 0 and (r < 0) != (u < 0) and 2 * abs(r) > abs(u):  # G92.TAPER
            raise alarm("GEOMETRY", "R", "G92.TAPER", line)
        cx = dx + 2 * r  # the cutting start X (R is a radius)
        s = sign(ax - cx)  # COM.SIDE
        if s == 0:
            raise alarm("GEOMETRY", "X", "COM.SIDE", line)
        per_increment = 10 if self.grid["increment"] == "isb" else 1
        no19 = half_up(self.params["no19_pullout"] * lead, 10 * per_increment)
        pull = self.jk_table(no19)
        if self.params["no107_pullout_speed"] != 0:  # G92.JK.8
            raise Alarm("UNSUPPORTED", None, "G92.JK.8", line)
        segment = None
        if pull is not None:
            (j, k), rule = pull
            segment = self.pullout(dx, dz, r, w, s, j, k, line), rule
        if starts > self.params["max_passes"]:  # PRJ.MAXPASS: one pass per start
            raise alarm("TOO_MANY_PASSES", "L", "PRJ.MAXPASS", line)
        # G92.PATH step ③: it starts at X₃ (the pull-out's end, or D.x) and must not run from
        # beyond A.x toward the part — refused on J when the pull-out carried X there, else on X.
        x3 = dx if segment is None else segment[0][1][0]
        if s * (ax - x3) < 0:
            raise alarm("GEOMETRY", "J" if s * (ax - dx) >= 0 else "X", "G92.PATH", line)
        self.events.append({"event": "pass", "index": self.run_index, "kind": "ROUGH",
                            "diameter_depth": abs(ax - cx), "rule": "G92.PATH"})
        for start in range(starts):
            angle = half_up(360_000 * start, starts)  # COM.MULTISTART
            self.rapid(cx, az, "G92.PATH")
            if segment is None:
                self.thread(dx, dz, lead, angle, "G92.PATH")
            else:
                (p1, p2), rule = segment
                self.thread(p1[0], p1[1], lead, angle, "G92.PATH")
                self.thread(p2[0], p2[1], lead, angle, rule)
            self.rapid(ax, self.z, "G92.PATH")
            self.rapid(ax, az, "G92.PATH")

    def jk_table(self, no19):
        """G92.JK.1–7: the pull-out amounts (short axis J, long axis K) and the deciding rule;
        JK.1's short axis is round(c·tan(5131°))."""
        j = None if self.j is None else abs(self.j)
        k = None if self.k is None else abs(self.k)
        if j is None and k is None:
            result = ((round_mul_tan_degrees(no19, self.params["p5131_chamfer_angle"]), no19), "G92.JK.1")
        elif j is None:
            result = ((no19, k or no19), "G92.JK.2")
        elif j == 0:
            return None  # G92.JK.4, G92.JK.6
        elif k is None:
            result = ((j, j), "G92.JK.3")
        elif k == 0:
            result = ((j, j), "G92.JK.5")
        else:
            result = ((j, k), "G92.PULLOUT")
        (jj, kk), _ = result
        return None if jj == 0 or kk == 0 else result

    def pullout(self, ex, ez, r, w, s, j, k, line):
        """G92.PULLOUT on the long axis (COM.LONGAXIS): the segment's start and end points."""
        z_long = abs(w) > abs(r)
        travel = abs(w) if z_long else abs(r)
        if k >= travel:
            raise alarm("GEOMETRY", "K", "G92.PULLOUT", line)
        sz = sign(w)
        if z_long:
            start = (ex + 2 * half_up(r * k, abs(w)), ez - sz * k)
            end_x = ex + 2 * s * j
            if PLANT_BUG:
                end_x += s  # the planted bug: one increment too far out
            return start, (end_x, ez)
        start = (ex + 2 * sign(r) * k, ez - sz * half_up(abs(w) * k, abs(r)))
        return start, (ex, ez - sz * j)


def m_code(b):
    """The block's M code as a number, or None (with a point or a sign)."""
    mw = b.words.get("M")
    return None if mw is None or mw.point or mw.negative else mw.mantissa


def read_area(program):
    """SUB.FIND: the blocks after the main program's first M02/M30 (a lexing alarm anywhere is
    the call's)."""
    area, ended = [], False
    for b in blocks(program):
        if ended:
            area.append(b)
        elif m_code(b) in (2, 30):
            ended = True
    return area


def is_program(b, n):
    """The block's O word is exactly n (O2000.0 too)."""
    o = b.words.get("O")
    return o is not None and not o.negative and o.mantissa == n * 10 ** o.decimals


def run(program, m):
    """Runs the main program and the subprograms it calls (SUB.CALL … SUB.NEST)."""
    main = blocks(program)
    stack = []  # [area, start, next, runs left]
    area, runs = None, 0
    while True:
        m.in_subprogram = bool(stack)
        if stack:
            f = stack[-1]
            if f[2] == len(f[0]):
                raise alarm("BLOCK_NOT_FOUND", "M", "SUB.RETURN", f[0][f[1]].line)
            b = f[0][f[2]]
            f[2] += 1
        else:
            b = next(main, None)
            if b is None:
                return
        flow = m.block(b)
        if flow == "end":
            return
        if flow == "return":
            f = stack[-1]
            f[3] -= 1
            if f[3] > 0:
                f[2] = f[1]
            else:
                stack.pop()
        elif flow != "next":
            _, n, r, line = flow
            if area is None:
                area = read_area(program)
            found = [i for i, a in enumerate(area) if is_program(a, n)]
            if len(found) != 1:
                raise alarm("BLOCK_NOT_FOUND", "P", "SUB.FIND", line)
            start = found[0]
            if not any(m_code(a) == 99 for a in area[start:]):
                raise alarm("BLOCK_NOT_FOUND", "M", "SUB.RETURN", area[start].line)
            if len(stack) >= SUB_LEVELS:
                raise alarm("NESTING", "P", "SUB.NEST", line)
            if runs + r > m.params["max_passes"]:
                raise alarm("TOO_MANY_PASSES", "P", "PRJ.MAXPASS", line)
            runs += r
            stack.append([area, start, start, r])


def expand(program, cfg):
    """The trace of a program as the protocol's JSON object."""
    m = Machine(cfg)
    alarm_json = None
    try:
        check_config(cfg)
        run(program, m)
    except Alarm as a:
        alarm_json = a.json()
    return {"grid": cfg["grid"], "events": m.events, "alarm": alarm_json}


def answer(line):
    """One request line -> one response object."""
    try:
        req = json.loads(line)
        rid = req["id"]
    except (ValueError, KeyError, TypeError) as e:
        return {"id": 0, "error": "bad request: %s" % e}
    if req.get("schema") == HELLO and not LEGACY and 1 in req.get("versions", []):
        # It answers in order whatever it is sent ahead: cyclecheck may pipeline requests.
        return {"schema": HELLO, "id": rid, "versions": [1], "pipeline": True}
    if req.get("schema") != SCHEMA:
        return {"id": rid, "error": "unsupported schema %r (this candidate speaks %s)" % (req.get("schema"), SCHEMA)}
    program = req["program"].encode("utf-8") if "program" in req else bytes.fromhex(req["program_hex"])
    if req["config"]["dialect"] not in ("gsk", "fanuc"):
        return {"id": rid, "error": "dialect %s is not implemented by this candidate" % req["config"]["dialect"]}
    try:
        return {"id": rid, "trace": expand(program, req["config"])}
    except OutOfScope as e:
        return {"id": rid, "error": str(e)}


def main():
    for line in sys.stdin:
        if line.strip():
            sys.stdout.write(json.dumps(answer(line), separators=(",", ":")) + "\n")
            sys.stdout.flush()


if __name__ == "__main__":
    main()
