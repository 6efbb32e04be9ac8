"""Luminous intensity distributions of luminaires: IES LM-63 and EULUMDAT files.

A :class:`Photometry` is the candela table of a luminaire over the type C
angles of both formats: ``C`` (degrees, the azimuth of the half-plane through
the luminaire's vertical axis, counter-clockwise seen from above, C = 0 along
the luminaire's length) and ``gamma`` (degrees from the nadir: 0 straight
down, 90 horizontal, 180 straight up). Between the measured angles the
intensity is interpolated linearly in C and in gamma (bilinear), as both
standards prescribe; the C planes a file leaves out by symmetry are mirrored;
outside the measured gamma range (a downlight measured over 0..90) the
intensity is 0.

Reading (:func:`read_photometry`):

- IES LM-63 (1995, 2002, 2019; 1986 and 1991 files, whose layout from
  ``TILT=`` on is the same, are read as 1995 ones) through ``photompy`` (its ``IESFile``), the
  ``.ies`` table times the file's candela multiplier and ballast factor;
  only type C photometry (the one of interior luminaires) is accepted.
- EULUMDAT (``.ldt``) through ``eulumdat-py`` (``pyldt.LdtReader``), its
  stored C planes as the symmetry flag ``Isym`` says, cd/klm scaled to the
  lamps' total flux and the file's conversion factor.

Both readers are checked here for what they let pass (a short table, an
empty field read as 0, angles out of order, negative or non-finite
intensities): every problem raises :class:`PhotometryFileError` with the file
name and the field (and, for IES headers, the line). See
docs/lighting_studies.md for why these two packages.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import InvalidLightError, MissingDependencyError

__all__ = ["Photometry", "PhotometryFileError", "read_photometry", "SYMMETRIES", "MAX_PHOTOMETRY_BYTES"]

#: C-plane symmetries: the half-planes a table holds; the others are mirrored from them.
SYMMETRIES = ("none", "axial", "bilateral_0_180", "bilateral_90_270", "quadrant")

#: Largest photometric file read (real files are a few kB to a few hundred kB).
MAX_PHOTOMETRY_BYTES = 8 * 1024 * 1024
#: Largest table (C planes x gamma angles).
MAX_TABLE = 361 * 721

_FEET = 0.3048
_IES_FIELDS = (
    "number of lamps", "lumens per lamp", "candela multiplier", "number of vertical angles",
    "number of horizontal angles", "photometric type", "units type", "width", "length", "height",
    "ballast factor", "future use / file generation type", "input watts",
)


class PhotometryFileError(InvalidLightError):
    """A photometric file (IES LM-63 or EULUMDAT) cannot be read, or holds an impossible table.

    The message starts with the file name and names the offending field
    (and the line, where the format has fixed lines).
    """


def _readonly(a: ArrayLike) -> NDArray[np.float64]:
    out = np.array(a, dtype=np.float64)
    out.setflags(write=False)
    return out


@dataclass(frozen=True, slots=True, eq=False)  # equal only to itself: its tables are arrays
class Photometry:
    """A luminaire's candela table over type C angles (see the module docstring).

    Parameters
    ----------
    c_angles : array_like, shape (nc,)
        C angles of the stored half-planes, degrees, increasing; their range
        fixes the symmetry: one plane (axial), 0..90 (quadrant), 0..180
        (bilateral about the C0-C180 plane), 90..270 (bilateral about the
        C90-C270 plane), or from 0 up to at most 360 (none).
    gamma_angles : array_like, shape (ng,)
        Gamma angles, degrees in [0, 180], increasing, at least 2.
    candela : array_like, shape (nc, ng)
        Luminous intensity of the luminaire in cd, finite and >= 0.
    lamp_flux : float, default nan
        Rated flux of the lamps in lm (nan for absolute photometry).
    lor : float, default nan
        Light output ratio as the file states it (luminaire / lamp flux);
        nan when the file has none (IES: :meth:`flux` / ``lamp_flux``).
    opening : tuple of 3 floats, default (0, 0, 0)
        Luminous opening ``(length, width, height)`` in metres, length along
        C0; a negative width marks a round (elliptical) opening of axes
        ``length`` x ``-width`` (a circle when they are equal).
    label : str
        The luminaire's name from the file.
    source : str
        The file's name ("analytic" for the constructors here).
    file_format : str
        ``"LM-63-2002"`` (the IES version), ``"EULUMDAT"``, or empty.

    Raises
    ------
    InvalidLightError
        On angles out of range or order, a table of the wrong shape, or
        negative or non-finite intensities.

    Examples
    --------
    >>> p = Photometry.isotropic(100.0)
    >>> float(p.intensity(0.0, 45.0)), round(p.flux(), 6) == round(400 * math.pi, 6)
    (100.0, True)
    """

    c_angles: NDArray[np.float64] = field(compare=False)
    gamma_angles: NDArray[np.float64] = field(compare=False)
    candela: NDArray[np.float64] = field(compare=False)
    lamp_flux: float = math.nan
    lor: float = math.nan
    opening: tuple[float, float, float] = (0.0, 0.0, 0.0)
    label: str = ""
    source: str = ""
    file_format: str = ""

    if TYPE_CHECKING:  # the constructor as callers call it: array-likes, checked in __post_init__
        def __init__(self, c_angles: ArrayLike, gamma_angles: ArrayLike, candela: ArrayLike,
                     lamp_flux: float = math.nan, lor: float = math.nan,
                     opening: tuple[float, float, float] = (0.0, 0.0, 0.0), label: str = "",
                     source: str = "", file_format: str = "") -> None: ...

    def __post_init__(self) -> None:
        err = InvalidLightError
        c = np.asarray(self.c_angles, dtype=np.float64).reshape(-1)
        g = np.asarray(self.gamma_angles, dtype=np.float64).reshape(-1)
        v = np.asarray(self.candela, dtype=np.float64)
        if len(c) < 1 or len(g) < 2:
            raise err(f"Photometry.gamma_angles needs >= 2 angles and c_angles >= 1, got {len(g)} and {len(c)}")
        if len(c) * len(g) > MAX_TABLE:
            raise err(f"Photometry.candela has {len(c)} x {len(g)} values, more than {MAX_TABLE}")
        for name, a, lo, hi in (("c_angles", c, 0.0, 360.0), ("gamma_angles", g, 0.0, 180.0)):
            if not np.all(np.isfinite(a)) or a.min() < lo - 1e-9 or a.max() > hi + 1e-9:
                raise err(f"Photometry.{name} must lie in [{lo:g}, {hi:g}] degrees, got {a.min():g} .. {a.max():g}")
            if np.any(np.diff(a) <= 0):
                k = int(np.argmax(np.diff(a) <= 0))
                raise err(f"Photometry.{name} must increase, got {a[k]:g} then {a[k + 1]:g}")
        if v.shape != (len(c), len(g)):
            raise err(f"Photometry.candela must have shape ({len(c)}, {len(g)}) (C planes, gamma), got {v.shape}")
        if not np.all(np.isfinite(v)) or v.min() < 0:
            i, j = np.argwhere(~np.isfinite(v) | (v < 0))[0]
            raise err(f"Photometry.candela must be finite and >= 0, got {v[i, j]} at C={c[i]:g}, gamma={g[j]:g}")
        _symmetry_of(c)  # raises on an unknown C range
        object.__setattr__(self, "c_angles", _readonly(c))
        object.__setattr__(self, "gamma_angles", _readonly(g))
        object.__setattr__(self, "candela", _readonly(v))
        for name in ("lamp_flux", "lor"):
            x = float(getattr(self, name))
            if not (math.isnan(x) or (math.isfinite(x) and x > 0)):
                raise err(f"Photometry.{name} must be > 0 (or nan when unknown), got {x}")
            object.__setattr__(self, name, x)
        op = tuple(float(x) for x in self.opening)
        if len(op) != 3 or not all(math.isfinite(x) for x in op) or op[0] < 0 or op[2] < 0:
            raise err(f"Photometry.opening must be finite (length >= 0, width, height >= 0), got {self.opening}")
        object.__setattr__(self, "opening", op)

    # ------------------------------------------------------------------ construction

    @classmethod
    def isotropic(cls, candela: float, *, label: str = "isotropic") -> Photometry:
        """A uniform point source of ``candela`` cd in every direction (flux ``4 pi I``)."""
        return cls([0.0], [0.0, 180.0], [[candela, candela]], label=label, source="analytic")

    @classmethod
    def lambertian(cls, peak: float, *, steps: int = 90, label: str = "lambertian") -> Photometry:
        """A downward Lambertian emitter, ``I = peak cos(gamma)`` sampled every ``90 / steps`` degrees.

        The table holds the cosine at its nodes; between them the intensity is
        the linear interpolant the standards prescribe (not the cosine).
        """
        g = np.linspace(0.0, 90.0, steps + 1)
        return cls([0.0], g, [peak * np.cos(np.radians(g))], label=label, source="analytic")

    # ------------------------------------------------------------------ evaluation

    @property
    def symmetry(self) -> str:
        """One of :data:`SYMMETRIES`, from the range of :attr:`c_angles`."""
        return _symmetry_of(self.c_angles)

    def intensity(self, c: ArrayLike, gamma: ArrayLike) -> NDArray[np.float64]:
        """Luminous intensity in cd at type C angles (degrees; broadcast together).

        Bilinear in C and gamma between the stored angles, the missing C
        planes mirrored by symmetry, 0 outside the measured gamma range.
        """
        cc, gg = np.broadcast_arrays(np.asarray(c, dtype=np.float64), np.asarray(gamma, dtype=np.float64))
        cf = _fold(np.mod(cc, 360.0), self.symmetry)
        ca, ga, v = self.c_angles, self.gamma_angles, self.candela
        # gamma weights
        inside = (gg >= ga[0] - 1e-12) & (gg <= ga[-1] + 1e-12)
        gq = np.clip(gg, ga[0], ga[-1])
        j = np.clip(np.searchsorted(ga, gq, side="right") - 1, 0, len(ga) - 2)
        t = (gq - ga[j]) / (ga[j + 1] - ga[j])
        if len(ca) == 1:
            row = v[0]
            out = (1 - t) * row[j] + t * row[j + 1]
            return np.where(inside, out, 0.0)
        # C planes, periodic when the table is full but does not reach 360
        cap, vp = ca, v
        if self.symmetry == "none" and ca[-1] - ca[0] < 360.0 - 1e-9:
            cap = np.append(ca, ca[0] + 360.0)
            vp = np.vstack([v, v[:1]])
        cq = np.where(cf < cap[0], cf + 360.0, cf) if self.symmetry == "none" else cf
        cq = np.clip(cq, cap[0], cap[-1])
        i = np.clip(np.searchsorted(cap, cq, side="right") - 1, 0, len(cap) - 2)
        s = (cq - cap[i]) / (cap[i + 1] - cap[i])
        out = (
            (1 - s) * ((1 - t) * vp[i, j] + t * vp[i, j + 1])
            + s * ((1 - t) * vp[i + 1, j] + t * vp[i + 1, j + 1])
        )
        return np.where(inside, out, 0.0)

    def flux(self) -> float:
        """Luminous flux of the interpolated distribution in lm, integrated exactly.

        The interpolant is linear in gamma at each C, so each gamma cell
        integrates against ``sin(gamma)`` in closed form; in C it is piecewise
        linear (trapezoids over the full circle, mirrored planes included).
        """
        ga = np.radians(self.gamma_angles)
        a, b = ga[:-1], ga[1:]
        h = b - a
        w_lo = np.cos(a) - (np.sin(b) - np.sin(a)) / h  # integral of sin * (1 - t)
        w_hi = -np.cos(b) + (np.sin(b) - np.sin(a)) / h  # integral of sin * t
        ring = self._c_integrals()  # integral over C (radians) at each gamma node
        return float(np.sum(w_lo * ring[:-1] + w_hi * ring[1:]))

    def _c_integrals(self) -> NDArray[np.float64]:
        ca, v = np.radians(self.c_angles), self.candela
        sym = self.symmetry
        if sym == "axial":
            return 2 * math.pi * v[0]
        trap = np.sum(0.5 * (v[1:] + v[:-1]) * np.diff(ca)[:, None], axis=0) if len(ca) > 1 else 0 * v[0]
        if sym == "quadrant":
            return 4 * trap
        if sym in ("bilateral_0_180", "bilateral_90_270"):
            return 2 * trap
        gap = 2 * math.pi - (ca[-1] - ca[0])
        return trap + (0.5 * (v[-1] + v[0]) * gap if gap > 1e-12 else 0.0)

    @property
    def computed_lor(self) -> float:
        """``flux() / lamp_flux`` (nan for absolute photometry)."""
        return self.flux() / self.lamp_flux if math.isfinite(self.lamp_flux) else math.nan

    def scaled(self, factor: float) -> Photometry:
        """The same table times ``factor`` (a multiplier, a maintenance or ballast factor)."""
        return Photometry(self.c_angles, self.gamma_angles, self.candela * float(factor), self.lamp_flux, self.lor,
                          self.opening, self.label, self.source, self.file_format)


def _symmetry_of(c: NDArray[np.float64]) -> str:
    if len(c) == 1:
        return "axial"
    lo, hi = float(c[0]), float(c[-1])
    if abs(lo) < 1e-9 and abs(hi - 90) < 1e-9:
        return "quadrant"
    if abs(lo) < 1e-9 and abs(hi - 180) < 1e-9:
        return "bilateral_0_180"
    if abs(lo - 90) < 1e-9 and abs(hi - 270) < 1e-9:
        return "bilateral_90_270"
    if abs(lo) < 1e-9 and hi > 180:
        return "none"
    raise InvalidLightError(
        f"Photometry.c_angles must be one angle, or span 0..90, 0..180, 90..270 or 0..(180, 360], got {lo:g}..{hi:g}"
    )


def _fold(c: NDArray[np.float64], symmetry: str) -> NDArray[np.float64]:
    """C in [0, 360) to the stored half-planes."""
    if symmetry == "quadrant":
        c = np.mod(c, 180.0)
        return np.where(c > 90.0, 180.0 - c, c)
    if symmetry == "bilateral_0_180":
        return np.where(c > 180.0, 360.0 - c, c)
    if symmetry == "bilateral_90_270":  # mirror C -> 180 - C
        return np.where(c < 90.0, 180.0 - c, np.where(c > 270.0, 540.0 - c, c))
    return c


# ---------------------------------------------------------------------------- reading


def read_photometry(path: str | os.PathLike[str]) -> Photometry:
    """Read an IES LM-63 (``.ies``) or EULUMDAT (``.ldt``) file.

    Parameters
    ----------
    path : str or path-like
        The file; its suffix (``.ies`` or ``.ldt``, any case) picks the format.

    Returns
    -------
    Photometry
        Intensities in cd of the luminaire as measured (IES: times the
        candela multiplier and the ballast factor; EULUMDAT: cd/klm times the
        lamps' flux in klm and the conversion factor).

    Raises
    ------
    PhotometryFileError
        On an unknown suffix, a file that is not a regular file or is larger
        than :data:`MAX_PHOTOMETRY_BYTES`, or a malformed file (the message
        names the field).
    MissingDependencyError
        If the reader package is not installed (``pip install 'isocsg[photometry]'``).
    """
    p = Path(path)
    suffix = p.suffix.lower()
    if suffix not in (".ies", ".ldt"):
        raise PhotometryFileError(f"{p.name}: unknown photometric format {p.suffix!r} (expected .ies or .ldt)")
    try:
        st = p.stat()
    except OSError as exc:
        raise PhotometryFileError(f"{p.name}: cannot read: {exc.strerror or exc}") from None
    if not p.is_file() or st.st_size > MAX_PHOTOMETRY_BYTES:
        raise PhotometryFileError(f"{p.name}: must be a regular file of at most {MAX_PHOTOMETRY_BYTES} bytes")
    if suffix == ".ies":
        return _read_ies(p)
    return _read_ldt(p)


def _fail(p: Path, message: str) -> PhotometryFileError:
    return PhotometryFileError(f"{p.name}: {message}")


def _ies_layout(p: Path, text: str) -> tuple[int, int]:
    """Check the TILT line and the 13 numbers of an IES header; returns the angle counts."""
    lines = text.splitlines()
    tilt = next((k for k, ln in enumerate(lines) if ln.strip().upper().startswith("TILT=")), None)
    if tilt is None:
        raise _fail(p, "TILT= line missing (IES LM-63 header)")
    value = lines[tilt].strip()[5:].strip().upper()
    if value != "NONE":
        raise _fail(p, f"line {tilt + 1}: TILT={value}: only TILT=NONE is supported (lamp tilt tables are not applied)")
    tokens: list[tuple[str, int]] = []
    for k in range(tilt + 1, len(lines)):
        tokens.extend((t, k + 1) for t in lines[k].replace(",", " ").split())
    if len(tokens) < 13:
        raise _fail(p, f"line {tilt + 2}: the IES header needs 13 numbers after TILT=NONE, found {len(tokens)}")
    nums = []
    for name, (tok, line) in zip(_IES_FIELDS, tokens[:13]):
        try:
            nums.append(float(tok))
        except ValueError:
            raise _fail(p, f"line {line}: {name}: not a number: {tok[:30]!r}") from None
        if not math.isfinite(nums[-1]):
            raise _fail(p, f"line {line}: {name}: must be finite, got {tok[:30]!r}")
    checks = [
        (3, nums[3] >= 2 and nums[3] == int(nums[3]), "an integer >= 2"),
        (4, nums[4] >= 1 and nums[4] == int(nums[4]), "an integer >= 1"),
        (5, nums[5] in (1, 2, 3), "1 (type C), 2 (type B) or 3 (type A)"),
        (6, nums[6] in (1, 2), "1 (feet) or 2 (metres)"),
        (2, nums[2] > 0, "> 0"),
        (10, nums[10] > 0, "> 0"),
        (1, nums[1] > 0 or nums[1] == -1, "> 0 (or -1 for absolute photometry)"),
    ]
    for k, ok, want in checks:
        if not ok:
            raise _fail(p, f"line {tokens[k][1]}: {_IES_FIELDS[k]}: must be {want}, got {tokens[k][0]!r}")
    if nums[5] != 1:
        raise _fail(p, f"line {tokens[5][1]}: photometric type: only type C (1) is supported, got {tokens[5][0]!r}")
    nv, nh = int(nums[3]), int(nums[4])
    if nv * nh > MAX_TABLE:
        raise _fail(p, f"line {tokens[3][1]}: the table of {nh} x {nv} values is larger than {MAX_TABLE}")
    need = 13 + nv + nh + nv * nh
    if len(tokens) < need:
        raise _fail(p, f"the candela table needs {nv} vertical angles, {nh} horizontal angles and {nv * nh} "
                    f"candela values, found {len(tokens) - 13} numbers in all")
    for tok, line in tokens[13:need]:
        try:
            float(tok)
        except ValueError:
            raise _fail(p, f"line {line}: angles or candela values: not a number: {tok[:30]!r}") from None
    return nv, nh


def _read_ies(p: Path) -> Photometry:
    raw = p.read_bytes()
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError:  # keywords in Latin-1 (accented names): its bytes are all text
        text = raw.decode("latin-1")
        raw = text.encode("utf-8")
    nv, nh = _ies_layout(p, text)
    try:
        from photompy import IESFile  # type: ignore[import-untyped]
    except ImportError as exc:
        raise MissingDependencyError("reading IES files needs photompy: pip install 'isocsg[photometry]'") from exc
    first_c = float(text.split("TILT=", 1)[1].split()[14 + nv]) if nh > 1 else 0.0
    if first_c != 0.0:  # LM-63 allows 90 .. 270; photompy 0.3 refuses any table not starting at C = 0
        raise _fail(p, f"horizontal angles {first_c:g} .. : tables over horizontal angles 90 .. 270 (bilateral "
                    "about the 90-270 plane) are not read by photompy; mirror them to 0 .. 180")
    first = text.lstrip("\ufeff").split("\n", 1)[0].strip().upper()
    version = first.split(":", 1)[1].strip() if ":" in first else ""
    if version not in ("LM-63-1995", "LM-63-2002", "LM-63-2019"):
        # LM-63-1986 (no version line) and -1991 ("IESNA91"): the layout from TILT= on is the same;
        # photompy reads only the versions with an "IESNA:" / "IES:" line, so it is given one
        if ":" in first:
            raise _fail(p, f"line 1: unknown IES version {first[:40]!r} (LM-63-1986 to -2019 are read)")
        body = text.split("\n", 1)[1] if first.startswith("IESNA") else text
        raw = ("IESNA:LM-63-1995\n" + body).encode("utf-8")
        version = "LM-63-1991" if first.startswith("IESNA") else "LM-63-1986"
    try:
        ies = IESFile.read(raw, strict=False)
    except Exception as exc:  # noqa: BLE001 - the reader's own errors, re-worded with the file name
        raise _fail(p, f"IES LM-63: {exc}") from None
    hdr, ph = ies.header, ies.photometry
    c = np.asarray(ph.phis, dtype=np.float64)
    g = np.asarray(ph.thetas, dtype=np.float64)
    v = np.asarray(ph.values, dtype=np.float64) * float(hdr.ballast_factor)
    if v.shape != (nh, nv):
        raise _fail(p, f"IES LM-63: candela table of shape {v.shape}, expected ({nh}, {nv})")
    unit = _FEET if int(hdr.units) == 1 else 1.0
    lamps = float(hdr.lumens_per_lamp) * int(hdr.num_lamps)
    w, ln, ht = float(hdr.width) * unit, float(hdr.length) * unit, abs(float(hdr.height)) * unit
    # LM-63: negative dimensions mark round shapes (circle: -d, -d; ellipse: -w, -l): kept as a negative width
    opening = (abs(ln), -abs(w), ht) if (w < 0 or ln < 0) else (ln, w, ht)
    label = str(hdr.keywords.get("LUMINAIRE", "") or hdr.keywords.get("LUMCAT", "") or "")
    try:
        return Photometry(c, g, v, lamps if lamps > 0 else math.nan, math.nan, opening, label.strip(),
                          p.name, version)
    except InvalidLightError as exc:
        raise _fail(p, str(exc).replace("Photometry.", "")) from None


def _ldt_field(p: Path, name: str, line: int, value: Any, ok: bool, want: str) -> None:
    if not ok:
        raise _fail(p, f"line {line}: {name}: must be {want}, got {value!r}")


def _read_ldt(p: Path) -> Photometry:
    try:
        from pyldt import LdtReader  # type: ignore[import-untyped]
    except ImportError as exc:
        raise MissingDependencyError(
            "reading EULUMDAT files needs eulumdat-py: pip install 'isocsg[photometry]'"
        ) from exc
    try:
        ldt = LdtReader.read(p, expand_symmetry=False)
    except Exception as exc:  # noqa: BLE001 - the reader's own errors, re-worded with the file name
        raise _fail(p, f"EULUMDAT: {exc}") from None
    h = ldt.header
    # the reader reads an empty field as 0 and a short table as short rows: check what the format needs
    _ldt_field(p, "Isym (symmetry)", 3, h.isym, h.isym in (0, 1, 2, 3, 4), "0, 1, 2, 3 or 4")
    _ldt_field(p, "Mc (number of C planes)", 4, h.mc, h.mc >= 1 and (h.isym in (0, 1) or h.mc % 4 == 0),
               ">= 1 (a multiple of 4 with Isym 2, 3 or 4)")
    _ldt_field(p, "Ng (number of gamma angles)", 6, h.ng, h.ng >= 2, ">= 2")
    if h.mc * h.ng > MAX_TABLE:
        raise _fail(p, f"line 4: the table of {h.mc} x {h.ng} values is larger than {MAX_TABLE}")
    flux = float(sum(h.lamp_flux))
    _ldt_field(p, "total luminous flux of lamps", 28, flux, math.isfinite(flux) and flux > 0, "> 0 lm")
    conv = float(h.conv_factor) if h.conv_factor else 1.0
    _ldt_field(p, "conversion factor", 24, h.conv_factor, math.isfinite(conv) and conv > 0, "> 0")
    if len(h.c_angles) != h.mc:
        raise _fail(p, f"C angles: expected Mc = {h.mc} values, found {len(h.c_angles)}")
    if len(h.g_angles) != h.ng:
        raise _fail(p, f"gamma angles: expected Ng = {h.ng} values, found {len(h.g_angles)}")
    rows = [list(r) for r in ldt.intensities]
    stored = {0: h.mc, 1: 1, 2: h.mc // 2 + 1, 3: h.mc // 2 + 1, 4: h.mc // 4 + 1}[h.isym]
    if len(rows) != stored or any(len(r) != h.ng for r in rows):
        found = sum(len(r) for r in rows)
        raise _fail(p, f"luminous intensities: Isym {h.isym} stores {stored} C planes x {h.ng} values = "
                    f"{stored * h.ng}, found {found}")
    ca = np.asarray(h.c_angles, dtype=np.float64)
    v = np.asarray(rows, dtype=np.float64) * (flux / 1000.0) * conv
    if h.isym == 0:
        c = ca
    elif h.isym == 1:
        c = ca[:1]
    elif h.isym == 2:
        c = ca[:stored]
    elif h.isym == 4:
        c = ca[:stored]
    else:  # Isym 3: planes C270 .. C90 through C0; by the symmetry C -> 180 - C they are C270 down to C90
        k0 = 3 * h.mc // 4
        if abs(ca[k0] - 270.0) > 1e-6:
            raise _fail(p, f"C angles: with Isym 3 the angle number {k0 + 1} must be 270, got {ca[k0]:g}")
        c = np.mod(180.0 - ca[(k0 + np.arange(stored)) % h.mc], 360.0)[::-1]
        v = v[::-1]
    lor = float(h.lorl) / 100.0 if h.lorl and h.lorl > 0 else math.nan
    opening = (float(h.length_lum_area) / 1000.0, float(h.width_lum_area) / 1000.0, 0.0)
    if h.width_lum_area == 0 and h.length_lum_area > 0:  # circular: the diameter and a width of 0
        opening = (opening[0], -opening[0], 0.0)
    try:
        return Photometry(c, np.asarray(h.g_angles, dtype=np.float64), v, flux, lor, opening,
                          str(h.luminaire_name).strip(), p.name, "EULUMDAT")
    except InvalidLightError as exc:
        raise _fail(p, str(exc).replace("Photometry.", "")) from None
