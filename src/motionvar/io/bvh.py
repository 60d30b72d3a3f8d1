"""BVH read and write.

Supported layout (covers CMU/cgspeed, Xia, Bandai-Namco, Aalto, DFKI and PyMO files):
every joint has exactly three rotation channels, in any order (orders may differ per
joint), and optionally three position channels (any order, anywhere in its channel
list). Joints with position channels only, or with no channels, are rejected with a
clear :class:`BVHError`.

Conventions:
- Rotation channels are intrinsic Euler angles in channel order (``Zrotation Xrotation
  Yrotation`` is scipy's ``"ZXY"``), in degrees; angles wrapped to 0..360 are fine.
  Quaternions are made sign-continuous over frames (:func:`qfix`).
- Position channel values *replace* the joint's OFFSET (as :func:`motionvar.core.fk`
  does with ``Motion.translations``). The root's go to ``Motion.root_pos``; those of
  other joints go to ``Motion.translations`` (NaN for joints without, and for the
  root); ``translations`` is None when only the root has position channels. A root
  without position channels gets ``root_pos`` = its OFFSET on every frame.
- ``scale`` is centimetres per file unit in both directions: :func:`read_bvh`
  multiplies every length by it, :func:`write_bvh` divides by it. For CMU files pass
  ``motionvar.core.CMU_UNIT_CM`` to both; for files in cm, 1.0; in mm, 0.1.
- The writer reproduces the per-joint layout recorded in ``Skeleton.rotation_orders``
  and ``Skeleton.position_channels``; position channels are always written in
  ``Xposition Yposition Zposition`` order before the rotations.
- ``Frames: 46.0`` (a float header, as in DFKI files) is read as 46.
"""

from __future__ import annotations

import re
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..core.motion import Motion
from ..core.quaternions import euler_to_quat, qfix, quat_to_euler, quat_to_scipy
from ..core.skeleton import Skeleton
from .atomic import atomic_write

_AXES = "XYZ"
_ROT_CHANNELS = {f"{a}rotation".lower(): a for a in _AXES}
_POS_CHANNELS = {f"{a}position".lower(): a for a in _AXES}
_FRAMES_RE = re.compile(r"^\s*Frames\s*:\s*(\S*)\s*$", re.IGNORECASE)
_FRAME_TIME_RE = re.compile(r"^\s*Frame\s+Time\s*:\s*(\S*)\s*$", re.IGNORECASE)
_MOTION_RE = re.compile(r"^[ \t]*MOTION[ \t]*$", re.MULTILINE)
FPS_RANGE = (1.0, 10_000.0)  # frame rates a motion capture file can plausibly have


class BVHError(ValueError):
    """A BVH file that cannot be read; the message is ``"{path}:{line}: {what}"``."""

    def __init__(self, path: str | Path, line: int | None, message: str) -> None:
        self.path, self.line = str(path), line
        where = f"{path}:{line}" if line is not None else f"{path}"
        super().__init__(f"{where}: {message}")


@dataclass
class _Hierarchy:
    """Joints parsed from the HIERARCHY section, before any scaling."""

    names: list[str] = field(default_factory=list)
    parents: list[int] = field(default_factory=list)
    offsets: list[np.ndarray] = field(default_factory=list)
    end_sites: dict[int, np.ndarray] = field(default_factory=dict)
    orders: list[str] = field(default_factory=list)
    rot_cols: list[list[int]] = field(default_factory=list)
    pos_cols: list[list[int] | None] = field(default_factory=list)
    n_channels: int = 0


class _Tokens:
    """Whitespace tokens of the header lines, each with its 1-based line number, split
    line by line as the parser asks for them: a file without a MOTION line is read only
    up to its first structural error, never tokenised whole."""

    def __init__(self, lines: list[str], path: Path, eof_line: int) -> None:
        self.lines = lines
        self.path = path
        self.eof_line = eof_line
        self._line = 0  # index of the next line to split
        self._buf: list[tuple[str, int]] = []
        self._k = 0  # position in _buf

    def _fill(self) -> bool:
        while self._k >= len(self._buf):
            if self._line >= len(self.lines):
                return False
            n = self._line + 1
            self._buf = [(t, n) for t in self.lines[self._line].split()]
            self._k = 0
            self._line += 1
        return True

    def peek(self) -> tuple[str | None, int]:
        return self._buf[self._k] if self._fill() else (None, self.eof_line)

    def next(self) -> tuple[str | None, int]:
        tok = self.peek()
        self.advance()
        return tok

    def advance(self) -> None:
        if self._fill():
            self._k += 1

    def error(self, line: int, message: str) -> BVHError:
        return BVHError(self.path, line, message)

    def floats(self, n: int, what: str, line: int) -> np.ndarray:
        vals = []
        for _ in range(n):
            tok, ln = self.peek()
            try:
                vals.append(float(tok))  # type: ignore[arg-type]
            except (TypeError, ValueError):
                raise self.error(ln, f"{what} needs {n} numbers; got {tok!r}") from None
            self.advance()
        arr = np.array(vals)
        if not np.all(np.isfinite(arr)):
            raise self.error(line, f"{what} has non-finite values {vals}")
        return arr


def _is_channel(tok: str | None) -> bool:
    return tok is not None and (tok.lower() in _ROT_CHANNELS or tok.lower() in _POS_CHANNELS)


def _parse_channels(t: _Tokens, h: _Hierarchy, joint: str, line: int) -> tuple[str, list[int], list[int] | None]:
    """Read ``CHANNELS n name...``; return (rotation order, rotation columns, xyz position columns)."""
    tok, ln = t.next()
    try:
        n = int(tok)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise t.error(ln, f"joint {joint}: bad CHANNELS count {tok!r} (expected an integer)") from None
    names = []
    for _ in range(n):
        tok, ln2 = t.peek()
        if not _is_channel(tok):
            raise t.error(
                ln2,
                f"joint {joint}: bad CHANNELS count: CHANNELS {n} at line {ln} lists {len(names)} "
                f"channel names, then {tok!r}",
            )
        names.append(tok)
        t.advance()
    tok, ln2 = t.peek()
    if _is_channel(tok):
        raise t.error(
            ln2,
            f"joint {joint}: bad CHANNELS count: CHANNELS {n} at line {ln} is followed by more channel names ({tok!r})",
        )
    lower = [c.lower() for c in names]
    rot = [(i, _ROT_CHANNELS[c]) for i, c in enumerate(lower) if c in _ROT_CHANNELS]
    pos = [(i, _POS_CHANNELS[c]) for i, c in enumerate(lower) if c in _POS_CHANNELS]
    if len(rot) != 3 or len({a for _, a in rot}) != 3 or len(pos) not in (0, 3) or len({a for _, a in pos}) != len(pos):
        raise t.error(
            ln,
            f"joint {joint}: unsupported CHANNELS {n} {' '.join(names)}: each joint needs three "
            f"rotation channels (one per axis, any order) and optionally three position channels",
        )
    base = h.n_channels
    h.n_channels += n
    order = "".join(a for _, a in rot)
    pos_cols = [base + i for a in _AXES for i, b in pos if b == a] if pos else None
    return order, [base + i for i, _ in rot], pos_cols


def _parse_end_site(t: _Tokens, h: _Hierarchy, joint_index: int, line: int) -> None:
    tok, ln = t.next()
    if tok != "Site":
        raise t.error(ln, f"expected 'Site' after 'End'; got {tok!r}")
    tok, ln = t.next()
    if tok != "{":
        raise t.error(ln, f"expected '{{' after End Site; got {tok!r}")
    tok, ln = t.next()
    if tok != "OFFSET":
        raise t.error(ln, f"End Site needs an OFFSET; got {tok!r}")
    h.end_sites[joint_index] = t.floats(3, "End Site OFFSET", ln)
    tok, ln = t.next()
    if tok != "}":
        raise t.error(ln, f"unbalanced braces: End Site opened at line {line} is not closed (got {tok!r})")


def _open_joint(t: _Tokens, h: _Hierarchy, name: str, parent: int, line: int) -> int:
    """Register joint ``name`` after checking its ``{``; returns its index."""
    if name in h.names:
        raise t.error(line, f"joint name {name!r} appears twice")
    tok, ln = t.next()
    if tok != "{":
        raise t.error(ln, f"expected '{{' after joint {name}; got {tok!r}")
    h.names.append(name)
    h.parents.append(parent)
    h.offsets.append(None)  # type: ignore[arg-type]
    h.orders.append("")
    h.rot_cols.append([])
    h.pos_cols.append(None)
    return len(h.names) - 1


def _parse_joints(t: _Tokens, h: _Hierarchy, root: str, line: int) -> None:
    """Parse the ROOT joint and everything below it: ``{ OFFSET ... CHANNELS ...
    children }``. Iterative (an explicit stack of open joints), so any nesting depth
    reads without recursion."""
    stack = [(_open_joint(t, h, root, -1, line), line)]  # (joint index, line of its name)
    has_channels = {stack[0][0]: False}
    while stack:
        j, jline = stack[-1]
        name = h.names[j]
        tok, ln = t.next()
        if tok == "OFFSET":
            h.offsets[j] = t.floats(3, f"joint {name}: OFFSET", ln)
        elif tok == "CHANNELS":
            if has_channels[j]:
                raise t.error(ln, f"joint {name}: second CHANNELS line")
            h.orders[j], h.rot_cols[j], h.pos_cols[j] = _parse_channels(t, h, name, ln)
            has_channels[j] = True
        elif tok == "JOINT":
            child, cl = t.next()
            if child is None or child in "{}":
                raise t.error(cl, f"JOINT without a name under {name}")
            c = _open_joint(t, h, child, j, cl)
            has_channels[c] = False
            stack.append((c, cl))
        elif tok == "End":
            _parse_end_site(t, h, j, ln)
        elif tok == "}":
            if h.offsets[j] is None:
                raise t.error(jline, f"joint {name} has no OFFSET")
            if not has_channels[j]:
                raise t.error(jline, f"joint {name} has no CHANNELS (each joint needs three rotation channels)")
            stack.pop()
        elif tok is None or tok == "MOTION":
            raise t.error(ln, f"unbalanced braces: joint {name} opened at line {jline} is never closed")
        else:
            raise t.error(ln, f"joint {name}: unexpected {tok!r} (expected OFFSET, CHANNELS, JOINT, End Site or '}}')")


def _parse_hierarchy(t: _Tokens) -> _Hierarchy:
    tok, ln = t.next()
    if tok != "HIERARCHY":
        raise t.error(
            ln, "missing HIERARCHY (" + ("the file is empty)" if tok is None else f"the file starts with {tok!r})")
        )
    tok, ln = t.next()
    if tok != "ROOT":
        raise t.error(ln, f"expected ROOT after HIERARCHY; got {tok!r}")
    name, nl = t.next()
    if name is None or name in "{}":
        raise t.error(nl, "ROOT without a name")
    h = _Hierarchy()
    _parse_joints(t, h, name, nl)
    tok, ln = t.peek()
    if tok == "}":
        raise t.error(ln, "unbalanced braces: '}' without a matching '{'")
    if tok == "ROOT":
        raise t.error(ln, "a second ROOT is not supported")
    if tok != "MOTION":
        raise t.error(
            ln, "missing MOTION after the hierarchy (found " + ("end of file)" if tok is None else f"{tok!r})")
        )
    return h


class _LineCursor:
    """The lines of ``text`` from offset ``pos`` (0-based line ``index``), one at a time, so
    that the frame data after the MOTION header is never split into lines."""

    def __init__(self, text: str, pos: int, index: int) -> None:
        self.text, self.pos, self.index = text, pos, index

    def next(self) -> str | None:
        """The line at the cursor (None at the end of the text); the cursor moves past it."""
        if self.pos >= len(self.text):
            return None
        end = self.text.find("\n", self.pos)
        end = len(self.text) if end < 0 else end
        line = self.text[self.pos : end]
        self.pos, self.index = end + 1, self.index + 1
        return line


def _header_value(cursor: _LineCursor, regex: re.Pattern, what: str, path: Path) -> tuple[str, int]:
    """Value of the next non-blank line, a ``what:`` line, and its 0-based line index."""
    line = cursor.next()
    while line is not None and not line.strip():
        line = cursor.next()
    m = regex.match(line) if line is not None else None
    if m is None:
        found = repr(line.strip()[:40]) if line is not None else "end of file"
        raise BVHError(path, cursor.index, f"missing '{what}' line in MOTION (found {found})")
    return m.group(1), cursor.index - 1


def _locate_frame_error(lines: list[str], first: int, n_frames: int, n_channels: int, path: Path) -> BVHError:
    """Find the first bad frame line (error path only: a Python loop over lines is fine here)."""
    count = 0
    for i in range(first, len(lines)):
        toks = lines[i].split()
        if not toks:
            continue
        count += 1
        if count > n_frames:
            return BVHError(path, i + 1, f"more frame lines than 'Frames: {n_frames}'")
        if len(toks) != n_channels:
            return BVHError(
                path, i + 1, f"frame {count} has {len(toks)} values; the hierarchy has {n_channels} channels"
            )
        for tok in toks:
            try:
                v = float(tok)
            except ValueError:
                return BVHError(path, i + 1, f"frame {count}: non-numeric value {tok!r}")
            if not np.isfinite(v):
                return BVHError(path, i + 1, f"frame {count}: non-finite value {tok!r}")
    if count < n_frames:
        return BVHError(path, len(lines), f"file ends after {count} frames but 'Frames: {n_frames}'")
    return BVHError(path, first + 1, "frame data cannot be parsed")


def _frame_values(body: str | bytes) -> np.ndarray | None:
    """(T, C) values of the whitespace-separated frame lines (blank lines skipped), or None
    where a value does not parse or a line has more or fewer values than the first (the caller
    then finds the line; it also rejects non-finite values, which may parse). pandas' C reader:
    the values ``np.loadtxt`` gives, bit for bit (tests/io/test_bvh_read_write.py), about 1.7x faster."""
    import csv
    import io

    import pandas as pd

    try:
        frame = pd.read_csv(
            io.BytesIO(body) if isinstance(body, bytes) else io.StringIO(body),
            sep=r"\s+",
            header=None,
            dtype=float,
            quoting=csv.QUOTE_NONE,
            na_filter=False,
        )
    except (ValueError, pd.errors.ParserError, pd.errors.EmptyDataError):  # a UnicodeDecodeError is a ValueError
        return None
    return frame.to_numpy()


def _parse_frames(
    text: str, start: int, index: int, n_channels: int, path: Path, raw: bytes | None = None
) -> tuple[np.ndarray, float]:
    """(T, C) channel values and the frame time from the lines of ``text`` after MOTION, which
    begin at offset ``start``, 0-based line ``index``. ``raw``: the file's bytes where each is
    one character of ``text`` (ASCII), parsed as they are instead of the text."""
    cursor = _LineCursor(text, start, index)
    val, k = _header_value(cursor, _FRAMES_RE, "Frames:", path)
    try:
        n_float = float(val)
    except ValueError:
        n_float = np.nan
    if not (np.isfinite(n_float) and n_float == int(n_float) and n_float >= 0):
        raise BVHError(path, k + 1, f"bad 'Frames:' value {val!r} (expected a whole number)")
    n_frames = int(n_float)
    if n_frames == 0:
        raise BVHError(path, k + 1, "zero frames ('Frames: 0')")
    val, k = _header_value(cursor, _FRAME_TIME_RE, "Frame Time:", path)
    try:
        frame_time = float(val)
    except ValueError:
        frame_time = np.nan
    if not (np.isfinite(frame_time) and frame_time > 0):
        raise BVHError(path, k + 1, f"bad 'Frame Time:' value {val!r} (expected a positive number of seconds)")
    fps = 1.0 / frame_time
    if not (FPS_RANGE[0] <= fps <= FPS_RANGE[1]):
        raise BVHError(
            path,
            k + 1,
            f"'Frame Time: {val}' means {fps:.4g} frames per second, outside "
            f"{FPS_RANGE[0]:g}-{FPS_RANGE[1]:,.0f} (the value is in seconds per frame)",
        )
    data = _frame_values(text[cursor.pos :] if raw is None else raw[cursor.pos :])
    if data is None or data.shape != (n_frames, n_channels) or not np.all(np.isfinite(data)):
        lines = text.split("\n")
        if lines[-1] == "":
            lines.pop()
        raise _locate_frame_error(lines, k + 1, n_frames, n_channels, path)
    return data, frame_time


def _skeleton(h: _Hierarchy, scale: float) -> Skeleton:
    return Skeleton(
        names=tuple(h.names),
        parents=np.array(h.parents),
        offsets=np.array(h.offsets) * scale,
        end_sites={j: o * scale for j, o in h.end_sites.items()},
        rotation_orders=tuple(h.orders),
        position_channels=tuple(p is not None for p in h.pos_cols),
    )


def _to_motion(h: _Hierarchy, data: np.ndarray, frame_time: float, scale: float) -> Motion:
    skeleton = _skeleton(h, scale)
    T, J = data.shape[0], len(h.names)
    rot_cols = np.array(h.rot_cols)  # (J, 3): each joint's angle columns in its channel order
    if len(set(h.orders)) == 1:  # one rotation order for the whole rig
        rotations = euler_to_quat(data[:, rot_cols], h.orders[0])
    else:
        rotations = np.empty((T, J, 4))
        for order in sorted(set(h.orders)):
            idx = np.array([j for j, o in enumerate(h.orders) if o == order])
            rotations[:, idx] = euler_to_quat(data[:, rot_cols[idx]], order)
    if h.pos_cols[0] is not None:
        root_pos = data[:, h.pos_cols[0]] * scale
    else:
        root_pos = np.broadcast_to(skeleton.offsets[0], (T, 3)).copy()
    translations = None
    moving = [j for j in range(1, J) if h.pos_cols[j] is not None]
    if moving:
        translations = np.full((T, J, 3), np.nan)
        translations[:, moving] = data[:, np.array([h.pos_cols[j] for j in moving])] * scale
    return Motion(skeleton, root_pos, qfix(rotations, axis=0), 1.0 / frame_time, translations)


def read_bvh(path: str | Path, scale: float = 1.0, encoding: str = "utf-8") -> Motion:
    """Read a BVH file; every length is multiplied by ``scale`` (cm per file unit).

    The file is text in ``encoding`` (UTF-8, with or without a byte-order mark, by
    default; pass e.g. ``"latin-1"`` for older files with accented joint names). Raises
    :class:`BVHError` naming the file and line for malformed input, including bytes that
    are not valid in ``encoding`` (never a silently garbled joint name).
    """
    path = Path(path)
    try:
        raw = path.read_bytes()
    except OSError as exc:
        raise BVHError(path, None, f"cannot read ({exc.strerror or exc})") from exc
    try:
        text = raw.decode(encoding)
    except UnicodeDecodeError as exc:
        line = raw.count(b"\n", 0, exc.start) + 1
        raise BVHError(
            path,
            line,
            f"byte 0x{raw[exc.start]:02x} is not valid {encoding} text (re-save the file "
            f"as UTF-8, or read it with the encoding it was written in)",
        ) from None
    except LookupError as exc:
        raise BVHError(path, None, f"unknown text encoding {encoding!r}") from exc
    if len(text) != len(raw) or "\r" in text:  # not ASCII with \n line ends: parse the text
        text, raw = text.removeprefix("\ufeff").replace("\r\n", "\n").replace("\r", "\n"), None
    m = _MOTION_RE.search(text)
    header = text if m is None else text[: m.end()]  # through the MOTION line
    lines = header.split("\n")
    if lines[-1] == "":
        lines.pop()  # the final newline does not start a line
    t = _Tokens(lines, path, eof_line=max(1, len(lines)))
    h = _parse_hierarchy(t)
    _, motion_line = t.peek()
    data, frame_time = _parse_frames(text, m.end() + 1, motion_line, h.n_channels, path, raw)
    return _to_motion(h, data, frame_time, scale)


def _depth_first(skeleton: Skeleton) -> list[int]:
    """Joint indices in the order a BVH hierarchy lists them (depth-first, children by index)."""
    children = [skeleton.children(j) for j in range(skeleton.n_joints)]
    order, stack = [], [0]
    while stack:
        j = stack.pop()
        order.append(j)
        stack += reversed(children[j])
    return order


def _hierarchy_text(skeleton: Skeleton, scale: float, fmt: str) -> list[str]:
    """Header lines for ``skeleton`` (offsets divided by ``scale``), depth-first."""
    out = ["HIERARCHY"]
    children = [skeleton.children(j) for j in range(skeleton.n_joints)]

    def vec(v: np.ndarray) -> str:
        return " ".join(fmt % x for x in np.asarray(v) / scale)

    def joint(j: int, depth: int) -> None:
        ind = "\t" * depth
        out.append(f"{ind}{'ROOT' if j == 0 else 'JOINT'} {skeleton.names[j]}")
        out.append(f"{ind}{{")
        out.append(f"{ind}\tOFFSET {vec(skeleton.offsets[j])}")
        rot = " ".join(f"{a}rotation" for a in skeleton.rotation_orders[j])
        if skeleton.position_channels[j]:
            out.append(f"{ind}\tCHANNELS 6 Xposition Yposition Zposition {rot}")
        else:
            out.append(f"{ind}\tCHANNELS 3 {rot}")
        for c in children[j]:
            joint(c, depth + 1)
        if j in skeleton.end_sites:
            out.extend(
                [f"{ind}\tEnd Site", f"{ind}\t{{", f"{ind}\t\tOFFSET {vec(skeleton.end_sites[j])}", f"{ind}\t}}"]
            )
        out.append(f"{ind}}}")

    joint(0, 0)
    return out


def _channel_data(motion: Motion, scale: float) -> np.ndarray:
    """(T, C) channel values in the layout of ``motion.skeleton``, lengths divided by ``scale``."""
    sk = motion.skeleton
    T, J = motion.n_frames, sk.n_joints
    local = np.broadcast_to(sk.offsets, (T, J, 3))
    if motion.translations is not None:
        local = np.where(np.isnan(motion.translations), local, motion.translations)
    local = local.copy()
    local[:, 0] = motion.root_pos
    angles = np.empty((T, J, 3))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # scipy's gimbal-lock warning: the angles still give the same rotation
        for order in sorted(set(sk.rotation_orders)):
            idx = np.array([j for j, o in enumerate(sk.rotation_orders) if o == order])
            angles[:, idx] = quat_to_euler(motion.rotations[:, idx], order)
    blocks = [
        np.concatenate([local[:, j] / scale, angles[:, j]], axis=1) if sk.position_channels[j] else angles[:, j]
        for j in _depth_first(sk)
    ]
    return np.concatenate(blocks, axis=1)


def _check_writable(motion: Motion, path: Path) -> None:
    sk = motion.skeleton
    bad = [n for n in sk.names if not n or any(c.isspace() for c in n)]
    if bad:
        raise ValueError(f"{path}: joint names with whitespace cannot be written to BVH: {bad}")
    bad_orders = [o for o in sk.rotation_orders if sorted(o.upper()) != list(_AXES)]
    if bad_orders:
        raise ValueError(f"{path}: rotation orders must be permutations of XYZ; got {bad_orders}")
    if not sk.position_channels[0] and not np.allclose(motion.root_pos, sk.offsets[0], atol=1e-6):
        raise ValueError(f"{path}: the root has no position channels but root_pos moves away from its offset")
    if not (np.all(np.isfinite(motion.root_pos)) and np.all(np.isfinite(motion.rotations))):
        raise ValueError(f"{path}: motion has non-finite root positions or rotations")


def write_bvh(path: str | Path, motion: Motion, scale: float = 1.0, fmt: str = "%.6f") -> None:
    """Write ``motion`` as BVH in the channel layout of its skeleton; atomic (no partial file).

    ``scale`` is cm per file unit, as in :func:`read_bvh`: lengths are *divided* by it
    (1.0 writes cm; ``CMU_UNIT_CM`` writes CMU units). ``fmt`` formats every value.
    """
    path = Path(path)
    _check_writable(motion, path)
    motion = motion.copy()
    motion.rotations = (
        quat_to_scipy(motion.rotations).as_quat(scalar_first=True).reshape(motion.rotations.shape)
    )  # normalised; raises on zero quaternions
    data = _channel_data(motion, scale)
    lines = _hierarchy_text(motion.skeleton, scale, fmt)
    lines += ["MOTION", f"Frames: {motion.n_frames}", f"Frame Time: {1.0 / motion.fps:.10g}"]
    row = " ".join([fmt] * data.shape[1]) + "\n"
    body = (row * data.shape[0]) % tuple(data.ravel().tolist())  # one C-level format call, no frame loop

    def write(tmp: str) -> None:
        with open(tmp, "w", encoding="utf-8", newline="\n") as f:
            f.write("\n".join(lines) + "\n")
            f.write(body)

    atomic_write(path, write)
