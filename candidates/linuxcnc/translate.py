"""Translate a cyclecheck program (the gsk/fanuc lathe dialect) into LinuxCNC rs274ngc — only
where the two dialects name the same thing. Returns (ngc_text, line_map) or raises Refuse.

- G32 X Z F → G33 X Z K (a constant-lead thread move; LinuxCNC refuses F beside G33, so the F
  goes on a line of its own before it, where it is the modal feed as in the source dialect);
  a block repeating G32 modally gets the modal lead as its K.
- G70/G71/G72 P(ns) Q(nf): the contour blocks N(ns)…N(nf) become a subroutine O<n> SUB and the
  cycle LinuxCNC's `G7x Q<n>`; G71/G72's first block gives I (depth of cut Δd, a radius here, so
  doubled on LinuxCNC's diameter X for G71) and R (retract e). FANUC's allowances U(Δu) W(Δw)
  translate the contour; LinuxCNC has no such words (its D keeps a normal distance), so the
  subroutine's absolute X/Z words are shifted by them — a translation, not a computation.
- U/W outside a G7x profile (LinuxCNC's U, W are other axes there) → X[#5420*2+u], Z[#5422+w]:
  the current position plus the increment, as the source dialect reads them.
- G40/G41/G42 are dropped (with nose radius 0 they change no path; else the program is
  refused), and so is a leading byte-order mark.
- G50 X Z (set the current position) → G92 X Z. N, O and T words are dropped (LinuxCNC reads N
  only at a line's start and O as a flow-control word). `;` ends a block: each goes on its own
  line (LinuxCNC reads `;` as a comment).
Refused: G33 with P (no start angle in LinuxCNC), G34 (no variable lead), I on a thread (no
threads per inch), G92/G90/G94/G76/G78/G73–G75/G83/G84 (other meanings in LinuxCNC), G50 S,
M98/M99 (FANUC subprograms; LinuxCNC's subroutines are O-words).
"""

import re

WORD = re.compile(r"([A-Za-z])\s*([+-]?(?:\d+\.?\d*|\.\d+))")
OTHER_MEANING = {92: "G92 (a coordinate offset in LinuxCNC)", 90: "G90 (absolute mode in LinuxCNC)",
                 94: "G94 (feed per minute in LinuxCNC)", 76: "G76 (LinuxCNC's own threading cycle)",
                 78: "G78", 73: "G73", 74: "G74", 75: "G75", 83: "G83", 84: "G84", 34: "G34 (no variable lead)"}


class Refuse(Exception):
    pass


def strip_comments(line):
    out, depth = [], 0
    for ch in line:
        if ch == "(":
            depth += 1
        elif ch == ")" and depth:
            depth -= 1
        elif depth == 0:
            out.append(ch)
    return "".join(out)


def words_of(text):
    """[(LETTER, text_number)] when the text is only words and blanks, else None."""
    rest = WORD.sub("", text)
    if rest.replace(" ", "").replace("\t", "").replace("\r", "").replace("%", ""):
        return None
    return [(m.group(1).upper(), m.group(2)) for m in WORD.finditer(text)]


def gnums(ws):
    return [float(v) for l, v in ws if l == "G"]


def fmt(v):
    return ("%.6f" % v).rstrip("0").rstrip(".") if v != int(v) else "%d" % v


def blocks_of(program):
    """[(line, words or None, raw)] one per ';'-separated block with text."""
    out = []
    for n, line in enumerate(program.split("\n"), start=1):
        for part in strip_comments(line).split(";"):
            if part.strip(" \t\r%"):
                out.append((n, words_of(part), part))
    return out


def n_index(blocks, p):
    return [i for i, (_, ws, _) in enumerate(blocks) if ws and any(l == "N" and float(v) == p for l, v in ws)]


def emit(ws):
    # N, O: see above. T (tool select; no motion in either dialect) is dropped: the gcode
    # module segfaults on any T word outside a running LinuxCNC (candidate.toml, [[finding]]).
    return " ".join(l + v for l, v in ws if l not in "NOT")


def absolute(ws):
    """U/W (incremental X/Z here; other axes in LinuxCNC outside a G7x profile) as X/Z relative
    to the current position: #5420 is LinuxCNC's current X as a radius, #5422 its Z."""
    out = []
    for l, v in ws:
        if l == "U":
            out.append(("X", "[#5420*2+%s]" % v))
        elif l == "W":
            out.append(("Z", "[#5422+%s]" % v))
        else:
            out.append((l, v))
    return out


def contour_sub(blocks, i, j, number, du, dw, keep_feed):
    """The contour blocks i..j as a subroutine, absolute X/Z shifted by (du, dw)."""
    lines = [("O%d SUB" % number, blocks[i][0])]
    for line, ws, raw in blocks[i:j + 1]:
        if ws is None:
            lines.append((raw.strip(), line))  # not words: LinuxCNC judges it as written
            continue
        out = []
        for l, v in ws:
            if l == "X" and du:
                v = fmt(float(v) + du)
            elif l == "Z" and dw:
                v = fmt(float(v) + dw)
            elif l in "NOST" or (l == "F" and not keep_feed):
                continue
            out.append((l, v))
        lines.append((emit(out), line))
    lines.append(("O%d ENDSUB" % number, blocks[j][0]))
    return lines


def translate(program, decimals, params):
    """params: the request's machine parameters; 5132 and 5133 (increments) give G71/G72's
    depth of cut and retract where no first block does, as on the machine."""
    if program.startswith("\ufeff"):
        program = program[1:]  # a byte-order mark is no program text (PRJ.LEX); LinuxCNC reads it as one
    blocks = blocks_of(program)
    if params.get("nose_radius", 0) and any(ws and any(l == "G" and float(v) in (41.0, 42.0) for l, v in ws) for _, ws, _ in blocks):
        raise Refuse("G41/G42 with a nose radius: LinuxCNC's compensation needs its tool table")
    # G40/G41/G42 with nose radius 0 change no path in the source dialect; LinuxCNC's G41/G42
    # would refuse G7x cycles and #5420 reads, so they are dropped.
    blocks = [(n, ws if ws is None else [(l, v) for l, v in ws if not (l == "G" and float(v) in (40.0, 41.0, 42.0))], raw)
              for n, ws, raw in blocks]
    body, subs, line_map = [], [], []
    unit = 10.0 ** -decimals
    dflt = (fmt(params.get("p5132_rough_depth", 1000) * unit), fmt(params.get("p5133_rough_retract", 500) * unit))
    mode, lead, g7x_first = None, None, {71: dflt, 72: dflt}
    skip_to, sub_no = -1, 100
    for i, (line, ws, raw) in enumerate(blocks):
        if i <= skip_to:
            continue
        if ws is None:
            body.append(raw.strip())
            line_map.append(line)
            continue
        gs = gnums(ws)
        letters = {l: v for l, v in ws}
        for g in gs:
            if g == int(g) and int(g) in OTHER_MEANING:
                raise Refuse("LinuxCNC has no translation for " + OTHER_MEANING[int(g)])
        if "F" in letters and not any(g in (70.0, 71.0, 72.0) for g in gs):
            lead = letters["F"]
        motion = [g for g in gs if g in (0.0, 1.0, 2.0, 3.0, 32.0, 33.0)]
        if motion:
            mode = motion[0]
        if "M" in letters and float(letters["M"]) in (98.0, 99.0):
            raise Refuse("M98/M99 (FANUC subprograms): LinuxCNC calls subroutines with O-words instead")
        if 50.0 in gs:
            if "S" in letters:
                raise Refuse("G50 S (spindle limit) has no LinuxCNC counterpart")
            out = [("G", "92")] + [(l, v) for l, v in ws if l in "XZ"]
            body.append(emit(out))
            line_map.append(line)
            continue
        cyc = [int(g) for g in gs if g in (70.0, 71.0, 72.0)]
        if cyc:
            c = cyc[0]
            if "P" not in letters and "Q" not in letters:
                if c == 70:
                    raise Refuse("G70 without P/Q")
                g7x_first[c] = (letters.get("U" if c == 71 else "W", dflt[0]), letters.get("R", dflt[1]))
                continue
            if "P" not in letters or "Q" not in letters:
                body.append("G%d" % c)  # LinuxCNC's own error: a cycle without its profile
                line_map.append(line)
                continue
            p, q = float(letters["P"]), float(letters["Q"])
            before = [k for k in n_index(blocks, p) if (k < i if c == 70 else k == i + 1)]
            ends = [k for k in n_index(blocks, q) if before and k >= before[0]]
            if len(before) != 1 or not ends:
                # No contour where the cycle needs it: LinuxCNC is given a profile subroutine
                # that does not exist, and reports its own error.
                body.append("G%d Q9999" % c)
                line_map.append(line)
                continue
            a, b = before[0], ends[0]
            du = float(letters.get("U", 0))
            dw = float(letters.get("W", 0))
            sub_no += 1
            subs.extend(contour_sub(blocks, a, b, sub_no, du, dw, keep_feed=(c == 70)))
            if "F" in letters:
                body.append("F" + letters["F"])
                line_map.append(line)
                lead = letters["F"]
            if c == 70:
                body.append("G70 Q%d D0 E0 P1" % sub_no)
            else:
                depth, retract = g7x_first[c]
                # LinuxCNC's I is the depth of cut as a radius even in G7 (measured), as Δd.
                body.append("G%d Q%d D0 I%s R%s" % (c, sub_no, depth, retract))
            line_map.append(line)
            if c != 70:
                skip_to = b  # CNT.FLOW: the contour is not run again as ordinary blocks
            continue
        if mode in (32.0, 33.0) and any(l in letters for l in "XZUW"):
            if mode == 33.0 and "P" in letters and float(letters["P"]) != 0:
                raise Refuse("G33 P (spindle start angle) other than 0: LinuxCNC's G33 has none")
            ws = [(l, v) for l, v in ws if l != "P"]  # P0: the index pulse, LinuxCNC's start
            if "I" in letters:
                raise Refuse("a thread lead in threads per inch (I): LinuxCNC's G33 takes K only")
            if "F" in letters:
                body.append("F" + letters["F"])
                line_map.append(line)
            out = [("G", "33") if (l == "G" and float(v) in (32.0, 33.0)) else (l, v) for l, v in ws if l != "F"]
            if lead is not None:
                out.append(("K", lead))  # else LinuxCNC's own error: G33 without K
            body.append(emit(absolute(out)))
            line_map.append(line)
            continue
        body.append(emit(absolute(ws)))
        line_map.append(line)
    return subs, body, line_map
