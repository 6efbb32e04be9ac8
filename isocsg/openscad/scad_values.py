"""OpenSCAD 2021.01's values, operators and built-in functions, for :mod:`isocsg.openscad.evaluate`.

Numbers are Python floats computed with the same double operations as OpenSCAD's C++ (its
degree trigonometry of ``degree_trig.cc``, ``round`` half away from zero, ``log(x)`` as
``ln(x) / ln(10)``, ...). Whatever OpenSCAD would answer with ``undef`` and a warning (a number
added to a vector, a bad argument, an index out of range) raises
:class:`~isocsg.openscad.scad_syntax.Declined` instead: the program reads such a file.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from decimal import ROUND_HALF_UP, Decimal
from typing import Any

from .scad_syntax import Declined

__all__ = ["Range", "Scope", "binary", "builtin_function", "cos_degrees", "export_number", "export_value",
           "sin_degrees", "truthy", "unary"]

_SQRT3 = 1.73205080756887719318
_SQRT3_4 = 0.86602540378443859659
_SQRT1_3 = 0.57735026918962573106
_SQRT1_2 = 0.7071067811865476  # M_SQRT1_2
_RAD2DEG = 57.2957795130823208767
_DEG2RAD = 0.017453292519943295769
_TRIG_HUGE = float((1 << 26) * 360.0 * (1 << 26))
#: The special variables OpenSCAD starts with (``$preview`` is declined: see Scope.lookup).
_SPECIALS = {"$fn": 0.0, "$fa": 12.0, "$fs": 2.0, "$t": 0.0}
#: Most values of a range read (OpenSCAD's loops stop at 10000 steps with an error).
MAX_RANGE = 10000


@dataclass(frozen=True, slots=True)
class Range:
    """``[begin : step : end]``."""

    begin: float
    step: float
    end: float

    def values(self) -> list[float]:
        """The values OpenSCAD's iterator gives (``begin + step * i``, its count as ``numValues``)."""
        b, s, e = self.begin, self.step, self.end
        if not all(math.isfinite(x) for x in (b, s, e)) or s == 0:
            raise Declined("a range with a zero or non-finite bound or step")
        if (s < 0 and b < e) or (s > 0 and b > e):
            return []
        if b == e:
            return [b]
        n = math.floor(math.nextafter((e - b) / s, 4294967295.0)) + 1
        if n > MAX_RANGE:
            raise Declined("a range of more than 10000 values")
        return [b + s * i for i in range(n)]


def _is_num(v: Any) -> bool:
    return type(v) is float


def _num(v: Any, what: str) -> float:
    if type(v) is not float:
        raise Declined(f"{what}: not a number")
    return v


def truthy(v: Any) -> bool:
    """OpenSCAD's ``toBool``."""
    if v is None:
        return False
    if type(v) is bool:
        return v
    if type(v) is float:
        return v != 0.0
    if isinstance(v, (str, list)):
        return len(v) > 0
    return True  # a range


def _wrap(x: float, period: float) -> float:
    if not (x < period and x >= 0.0):
        if x < _TRIG_HUGE and x > -_TRIG_HUGE:
            x -= period * math.floor(x / period)
        else:
            return math.nan
    return x


def sin_degrees(x: float) -> float:
    """``sin_degrees`` of OpenSCAD 2021.01 (exact at multiples of 30 and 45 degrees)."""
    x = _wrap(x, 360.0)
    if math.isnan(x):
        return x
    oppose = x >= 180.0
    if oppose:
        x -= 180.0
    if x > 90.0:
        x = 180.0 - x
    if x < 45.0:
        x = 0.5 if x == 30.0 else math.sin(x * _DEG2RAD)
    elif x == 45.0:
        x = _SQRT1_2
    elif x == 60.0:
        x = _SQRT3_4
    else:
        x = math.cos((90.0 - x) * _DEG2RAD)
    return -x if oppose else x


def cos_degrees(x: float) -> float:
    """``cos_degrees`` of OpenSCAD 2021.01."""
    x = _wrap(x, 360.0)
    if math.isnan(x):
        return x
    oppose = x >= 180.0
    if oppose:
        x -= 180.0
    if x > 90.0:
        x = 180.0 - x
        oppose = not oppose
    if x > 45.0:
        x = 0.5 if x == 60.0 else math.sin((90.0 - x) * _DEG2RAD)
    elif x == 45.0:
        x = _SQRT1_2
    elif x == 30.0:
        x = _SQRT3_4
    else:
        x = math.cos(x * _DEG2RAD)
    return -x if oppose else x


def tan_degrees(x: float) -> float:
    """``tan_degrees`` of OpenSCAD 2021.01."""
    if not math.isfinite(x) or abs(x) >= _TRIG_HUGE:
        raise Declined("tan of a huge angle")
    cycles = math.floor(x / 180.0)
    if not (x < 180.0 and x >= 0.0):
        x -= 180.0 * cycles
    oppose = x > 90.0
    if oppose:
        x = 180.0 - x
    if x == 0.0:
        x = 0.0 if cycles % 2 == 0 else -0.0
    elif x == 30.0:
        x = _SQRT1_3
    elif x == 45.0:
        x = 1.0
    elif x == 60.0:
        x = _SQRT3
    elif x == 90.0:
        x = math.inf if cycles % 2 == 0 else -math.inf
    else:
        x = math.tan(x * _DEG2RAD)
    return -x if oppose else x


def c_round(x: float) -> float:
    """C's ``round``: half away from zero."""
    if not math.isfinite(x):
        return x
    r = math.floor(abs(x))
    if abs(x) - r >= 0.5:
        r += 1
    return math.copysign(float(r), x)


def _inverse(f: Callable[[float], float], back: Callable[[float], float], x: float) -> float:
    if not -1.0 <= x <= 1.0 and f is not math.atan:
        raise Declined("asin/acos outside [-1, 1]")
    degs = f(x) * _RAD2DEG
    whole = c_round(degs)
    return whole if back(whole) == x else degs


def _atan2(y: float, x: float) -> float:
    degs = math.atan2(y, x) * _RAD2DEG
    whole = c_round(degs)
    return whole if abs(degs - whole) < 3.0e-14 else degs


def _log(*a: float) -> float:
    x, y = (10.0, a[0]) if len(a) == 1 else (a[0], a[1])
    if x <= 0 or y <= 0:
        raise Declined("log of a number <= 0")
    return math.log(y) / math.log(x)


def _sqrt(x: float) -> float:
    if x < 0:
        raise Declined("sqrt of a negative number")
    return math.sqrt(x)


def _ln(x: float) -> float:
    if x <= 0:
        raise Declined("ln of a number <= 0")
    return math.log(x)


def _pow(x: float, y: float) -> float:
    try:
        return math.pow(x, y)
    except (ValueError, OverflowError, ZeroDivisionError):
        raise Declined("pow out of range") from None


def _sign(x: float) -> float:
    return -1.0 if x < 0 else (1.0 if x > 0 else 0.0)


def _exp(x: float) -> float:
    try:
        return math.exp(x)
    except OverflowError:
        raise Declined("exp overflow") from None


_NUMERIC: dict[str, tuple[Callable[..., float], tuple[int, ...]]] = {
    "sin": (sin_degrees, (1,)), "cos": (cos_degrees, (1,)), "tan": (tan_degrees, (1,)),
    "asin": (lambda x: _inverse(math.asin, sin_degrees, x), (1,)),
    "acos": (lambda x: _inverse(math.acos, cos_degrees, x), (1,)),
    "atan": (lambda x: _inverse(math.atan, tan_degrees, x), (1,)),
    "atan2": (_atan2, (2,)), "abs": (abs, (1,)), "sign": (_sign, (1,)), "sqrt": (_sqrt, (1,)),
    "pow": (_pow, (2,)), "exp": (_exp, (1,)), "ln": (_ln, (1,)), "log": (_log, (1, 2)),
    "floor": (lambda x: float(math.floor(x)) if math.isfinite(x) else x, (1,)),
    "ceil": (lambda x: float(math.ceil(x)) if math.isfinite(x) else x, (1,)),
    "round": (c_round, (1,)),
}


def _min_max(name: str, args: list[Any]) -> float:
    items = args[0] if len(args) == 1 and isinstance(args[0], list) else args
    if len(args) == 1 and not isinstance(args[0], list):
        raise Declined(f"{name} of one number")
    if not items or not all(_is_num(v) for v in items):
        raise Declined(f"{name} of non-numbers")
    best = items[0]
    for v in items[1:]:  # OpenSCAD keeps the first of equal values; NaN declined below
        if (v < best) if name == "min" else (v > best):
            best = v
    if any(math.isnan(v) for v in items):
        raise Declined(f"{name} of NaN")
    return float(best)


def _lookup(args: list[Any]) -> float:
    """OpenSCAD 2021.01's ``lookup(key, table)`` (``func.cc``): the value at ``key`` of the
    table's ``[key, value]`` rows, linear between the nearest keys below and above, the end
    value beyond the ends. A table with any other row, or a key that is not finite, is declined
    (the program skips such rows or answers undef)."""
    if len(args) != 2 or not _is_num(args[0]) or not math.isfinite(args[0]) or not isinstance(args[1], list):
        raise Declined("lookup: bad arguments")
    rows = args[1]
    if not rows or not all(isinstance(r, list) and len(r) == 2 and all(_is_num(x) and math.isfinite(x) for x in r)
                           for r in rows):
        raise Declined("lookup: a table of [key, value] rows of finite numbers")
    p = args[0]
    low_p, low_v = rows[0]
    high_p, high_v = low_p, low_v
    for this_p, this_v in rows[1:]:
        if this_p <= p and (this_p > low_p or low_p > p):
            low_p, low_v = this_p, this_v
        if this_p >= p and (this_p < high_p or high_p < p):
            high_p, high_v = this_p, this_v
    if p <= low_p:
        return float(high_v)
    if p >= high_p:
        return float(low_v)
    f = (p - low_p) / (high_p - low_p)
    return float(high_v * f + low_v * (1 - f))


def _cross(args: list[Any]) -> Any:
    """``cross(a, b)`` of two vectors of 3 (or 2) finite numbers, as ``func.cc`` computes it."""
    if (len(args) != 2 or not all(isinstance(v, list) and len(v) == len(args[0]) in (2, 3) for v in args)
            or not all(_is_num(x) and math.isfinite(x) for v in args for x in v)):
        raise Declined("cross: bad arguments (a warning)")
    a, b = args
    if len(a) == 2:
        return a[0] * b[1] - a[1] * b[0]
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def builtin_function(name: str, args: list[Any]) -> Any:
    """The value of a built-in function call (positional arguments), or :class:`Declined`."""
    if name in _NUMERIC:
        f, counts = _NUMERIC[name]
        if len(args) not in counts or not all(_is_num(v) for v in args):
            raise Declined(f"{name}: bad arguments")
        return float(f(*args))
    if name in ("min", "max"):
        return _min_max(name, args)
    if name == "lookup":
        return _lookup(args)
    if name == "norm":
        if len(args) != 1 or not isinstance(args[0], list) or not all(_is_num(v) for v in args[0]):
            raise Declined("norm: bad arguments")
        total = 0.0
        for x in args[0]:
            total += x * x
        return math.sqrt(total)
    if name == "cross":
        return _cross(args)
    if name == "len":
        if len(args) != 1 or not isinstance(args[0], (list, str)):
            raise Declined("len: bad arguments")
        return float(len(args[0]))
    if name == "concat":
        out: list[Any] = []
        for v in args:
            if isinstance(v, Range):
                raise Declined("concat of a range")
            out.extend(v) if isinstance(v, list) else out.append(v)
        if len(out) > MAX_RANGE * 100:
            raise Declined("a vector of more than a million values")
        return out
    raise Declined(f"unknown function {name}")


def unary(op: str, v: Any) -> Any:
    """``-v`` or ``!v``."""
    if op == "!":
        return not truthy(v)
    if _is_num(v):
        return -v
    if isinstance(v, list) and all(_is_num(x) for x in v):
        return [-x for x in v]
    raise Declined("negation of a non-number")


def _numbers(v: Any) -> bool:
    return isinstance(v, list) and all(_is_num(x) for x in v)


def _equal(a: Any, b: Any) -> bool:
    if type(a) is not type(b):
        return False
    if isinstance(a, list):
        return len(a) == len(b) and all(_equal(x, y) for x, y in zip(a, b, strict=True))
    return bool(a == b)


def binary(op: str, a: Any, b: Any) -> Any:
    """``a op b`` for the arithmetic and comparison operators (``&&``/``||`` are the caller's)."""
    if op in ("==", "!="):
        if isinstance(a, Range) or isinstance(b, Range):
            raise Declined("a range compared")
        return _equal(a, b) == (op == "==")
    if op in ("<", "<=", ">", ">="):
        if not ((_is_num(a) and _is_num(b)) or (type(a) is str and type(b) is str)):
            raise Declined("comparison of other values than numbers or strings")
        return {"<": a < b, "<=": a <= b, ">": a > b, ">=": a >= b}[op]
    if _is_num(a) and _is_num(b):
        if op == "+":
            return a + b
        if op == "-":
            return a - b
        if op == "*":
            return a * b
        if op == "/":
            return a / _divisor(b)
        if op == "%":
            return math.fmod(a, _divisor(b)) if math.isfinite(a) else math.nan
        if op == "^":
            return _pow(a, b)
    if op in ("+", "-") and _numbers(a) and _numbers(b) and len(a) == len(b):
        return [x + y if op == "+" else x - y for x, y in zip(a, b, strict=True)]
    if op == "*" and _is_num(a) and _numbers(b):
        return [a * y for y in b]
    if op in ("*", "/") and _numbers(a) and _is_num(b):
        return [x * b for x in a] if op == "*" else [x / _divisor(b) for x in a]
    raise Declined(f"operator {op} on these values")


def _divisor(b: float) -> float:
    if b == 0:
        raise Declined("a division by zero")
    return b


def export_number(v: Any, *, value: bool = False) -> float:
    """A number as the export prints it (6 significant digits) and parse_csg reads it back.

    The nodes print their own fields through C++ streams (glibc: an exact tie to even), and
    OpenSCAD values (``multmatrix``, a polyhedron's or polygon's lists: ``value=True``) through
    double-conversion (a tie away from zero): ``100.0625`` is ``100.062`` in a cube's size and
    ``100.063`` in a matrix.
    """
    if type(v) is not float or not math.isfinite(v):
        raise Declined("a non-finite or non-number argument")
    if v == 0:
        return 0.0
    if not value:
        return float(f"{v:.6g}")  # Python rounds exact ties to even, as glibc does
    d = Decimal(v)
    return float(d.quantize(Decimal(1).scaleb(d.adjusted() - 5), ROUND_HALF_UP))


def export_value(v: Any) -> Any:
    """A polyhedron's or polygon's list argument as the export prints it (numbers and lists)."""
    if isinstance(v, list):
        return [export_value(x) for x in v]
    return export_number(v, value=True)


class Scope:
    """A scope: its variables, modules and functions; ``lex`` for names, ``dyn`` for ``$`` names
    (``$children`` excepted: OpenSCAD finds it through the definitions, ``lex``); a user module's
    scope keeps its ``call`` (what ``children()`` reads)."""

    __slots__ = ("vars", "pending", "modules", "functions", "lex", "dyn", "call", "uses")

    def __init__(self, lex: Scope | None, dyn: Scope | None, variables: dict[str, Any] | None = None) -> None:
        self.vars: dict[str, Any] = dict(variables or {})
        self.pending: set[str] = set()
        self.modules: dict[str, tuple[Any, Scope]] = {}
        self.functions: dict[str, tuple[Any, Scope]] = {}
        self.lex, self.dyn = lex, dyn
        self.call: Any = None
        self.uses: list[Scope] = []  # a file's used files (their own modules and functions only)

    def lookup(self, name: str) -> Any:
        if name == "$preview":  # the program's -D $preview=false comes after the file's assignments
            raise Declined("$preview")
        frame: Scope | None = self
        while frame is not None:
            if name in frame.pending:
                raise Declined(f"{name} used before its assignment")
            if name in frame.vars:
                return frame.vars[name]
            frame = frame.dyn if name.startswith("$") and name != "$children" else frame.lex
        if name in _SPECIALS:
            return _SPECIALS[name]
        if name == "PI":
            return math.pi
        raise Declined(f"unknown variable {name}")

    def find(self, table: str, name: str) -> tuple[Any, Scope] | None:
        frame: Scope | None = self
        while frame is not None:
            found = getattr(frame, table).get(name)
            if found is None and frame.uses:  # after the file's own: the used files' definitions
                hits = [h for lib in frame.uses if (h := getattr(lib, table).get(name)) is not None]
                if len(hits) > 1:
                    raise Declined(f"{name} defined in two used files (which one OpenSCAD takes is not defined)")
                found = hits[0] if hits else None
            if found is not None:
                return found  # type: ignore[no-any-return]
            frame = frame.lex
        return None
