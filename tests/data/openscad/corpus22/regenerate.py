"""Recompute ``manifest.json``: OpenSCAD's STL volume, nodes and tolerance class of every model.

Run from anywhere (needs the ``openscad`` program and trimesh)::

    python tests/data/openscad/corpus22/regenerate.py            # new or edited models only
    python tests/data/openscad/corpus22/regenerate.py --all      # every model
    python tests/data/openscad/corpus22/regenerate.py NAME ...   # these models
    python tests/data/openscad/corpus22/regenerate.py --files    # also rewrite plate.dxf (ezdxf)

A model is a ``.scad`` file (its ``.csg`` export is written beside it, and the tests load that
export, so that they run without the program) or a hand-written ``.csg`` (loaded as it is).
Every ``*.scad`` and ``*.csg`` of this folder that is not the export of a ``.scad`` gets an entry;
entries may also name models of the per-feature folders (``"file": "../revolve/dome.scad"``),
whose ``.csg`` exports those folders' own scripts keep. For each entry the script records:

- ``stl_volume``: the volume (trimesh) of ``openscad --render -D '$fn=96' -o model.stl model``
  (an explicit ``$fn`` in the model wins over ``-D``), and ``command``, that command; an entry's
  ``"define_fn": false`` leaves ``-D`` out, for a model meant for OpenSCAD's default ``$fa`` and
  ``$fs`` polygons (which isocsg then builds, such as a scaled extrusion of a default circle);
- ``nodes``: the node names of the ``.csg`` (without ``group``), with the modifiers ``%`` and
  ``*`` of the model's text;
- ``class``: ``polygonal`` when every round node (circle, sphere, cylinder, rotate_extrude,
  offset with ``r``) has an explicit ``$fn`` in 3..64 (isocsg then builds OpenSCAD's own
  polygonal solid) and there is no text, else ``round``; an entry's ``"reference"`` (a mesh
  file, for formats OpenSCAD 2021.01 cannot import) replaces the STL by trimesh's volume of it;
- ``sha256`` of the model's text, so that the tests can say when an entry is stale.
"""

from __future__ import annotations

import hashlib
import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path

DIR = Path(__file__).resolve().parent
MANIFEST = DIR / "manifest.json"
FN = 96
FN_MAX = 64  # isocsg.openscad.FN_MAX: explicit $fn up to this makes OpenSCAD's polygonal solid
ROUND_NODES = {"circle", "sphere", "cylinder", "rotate_extrude"}
CLASSES = {
    "round": {"rtol": 0.005, "about": "round at high $fn: isocsg's exact volume within 0.5 % of OpenSCAD's STL at $fn = 96"},
    "polygonal": {
        "rtol": 2e-5,
        "about": "polygonal: OpenSCAD's own solid (every curve has an explicit $fn <= 64, or none has curves), "
        "exact to the STL's digits",
    },
}
_NODE = re.compile(r"^\s*([%*!#]?)\s*([A-Za-z_]\w*)\s*\(")
_CALL = re.compile(r"(?<![\w$\"])([A-Za-z_]\w*)\s*\(")
_FN = re.compile(r"\$fn\s*=\s*([0-9.]+)")
_MODIFIER = re.compile(r"(?:^|[;{}])\s*([%*])\s*[A-Za-z_]", re.M)


def openscad_version() -> str:
    out = subprocess.run(["openscad", "--version"], capture_output=True, text=True, check=True)
    return (out.stdout + out.stderr).strip()


def _command(model: Path, define_fn: bool = True) -> list[str]:
    fn = ["-D", f"$fn={FN}"] if define_fn else []
    return ["openscad", "--render", *fn, "-o", f"{model.stem}.stl", model.name]


def _stl_volume(model: Path, define_fn: bool = True) -> float:
    import trimesh

    with tempfile.TemporaryDirectory() as tmp:
        stl = Path(tmp) / f"{model.stem}.stl"
        cmd = _command(model, define_fn)
        cmd[-2] = str(stl)
        subprocess.run(cmd, cwd=model.parent, capture_output=True, check=True, timeout=1800)
        return float(trimesh.load(stl, force="mesh").volume)


def _csg_of(model: Path) -> Path:
    return model if model.suffix == ".csg" else model.with_suffix(".csg")


def nodes_and_class(model: Path) -> tuple[list[str], str]:
    """The ``.csg``'s node names and modifiers, and the tolerance class they imply."""
    names: set[str] = set()
    polygonal = True
    for line in _strip_comments(_csg_of(model).read_text()).splitlines():
        m = _NODE.match(line)
        if m is None:
            continue
        if m.group(1) in "%*" and m.group(1):
            names.add(m.group(1))
        # a hand-written line may chain nodes: translate(...) rotate(...) cylinder(...)
        fn = _FN.search(line)
        for name in _CALL.findall(line):
            names.add(name)
            is_round = name in ROUND_NODES or (name == "offset" and re.search(r"\br\s*=", line) is not None)
            if name == "text" or (is_round and (fn is None or not 3 <= float(fn.group(1)) <= FN_MAX)):
                polygonal = False
    names.update(m.group(1) for m in _MODIFIER.finditer(_strip_comments(model.read_text())))
    names.discard("group")
    return sorted(names), "polygonal" if polygonal else "round"


def _strip_comments(text: str) -> str:
    return re.sub(r"//[^\n]*|/\*.*?\*/", "", text, flags=re.S)


def _own_models() -> list[Path]:
    scad = sorted(DIR.glob("*.scad"))
    stems = {p.stem for p in scad}
    hand = [p for p in sorted(DIR.glob("*.csg")) if p.stem not in stems]
    return scad + hand


def regenerate(entry: dict[str, object], version: str) -> None:
    model = (DIR / str(entry["file"])).resolve()
    if model.parent == DIR and model.suffix == ".scad":
        subprocess.run(["openscad", "-o", model.with_suffix(".csg").name, model.name], cwd=DIR, capture_output=True, check=True)
    nodes, cls = nodes_and_class(model)
    entry["nodes"] = nodes
    entry["class"] = cls
    entry["sha256"] = hashlib.sha256(model.read_bytes()).hexdigest()
    if model.suffix == ".scad":
        entry["csg"] = str(entry["file"])[: -len(".scad")] + ".csg"
    ref = entry.get("reference")
    if ref is not None:
        import trimesh

        entry["stl_volume"] = float(trimesh.load(DIR / str(ref), force="mesh").volume)
        entry["command"] = f"trimesh.load({Path(str(ref)).name!r}).volume (OpenSCAD 2021.01 cannot import this format)"
        entry["class"] = "polygonal"
    else:
        define_fn = bool(entry.get("define_fn", True))
        entry["stl_volume"] = _stl_volume(model, define_fn)
        entry["command"] = " ".join(c if c != f"$fn={FN}" else f"'$fn={FN}'" for c in _command(model, define_fn))
    entry["openscad"] = version


def write_drawings() -> None:
    """``plate.dxf``: a notched outline of LINEs with a CIRCLE hole (OpenSCAD draws the circle
    with its own segments, from ``$fn``, ``$fa`` and ``$fs``)."""
    import ezdxf

    doc = ezdxf.new("R12")
    msp = doc.modelspace()
    outline = [(0, 0), (40, 0), (40, 25), (25, 25), (20, 18), (15, 25), (0, 25)]
    for a, b in zip(outline, outline[1:] + outline[:1]):
        msp.add_line(a, b)
    msp.add_circle((10, 10), 4)
    doc.saveas(DIR / "plate.dxf")


def _save(update: dict[str, dict[str, object]]) -> None:
    """Write the given entries into the manifest as it is now (read again: saved after each model)."""
    data = json.loads(MANIFEST.read_text()) if MANIFEST.is_file() else {"models": {}}
    models = {**data["models"], **update}
    data = {
        "about": "issue 22's OpenSCAD corpus: each model, the nodes it uses, the volume of OpenSCAD's STL export of it "
        "and the command that made it, its tolerance class; regenerate.py recomputes them",
        "classes": CLASSES,
        "models": dict(sorted(models.items())),
    }
    MANIFEST.write_text(json.dumps(data, indent=1) + "\n")


def main(argv: list[str]) -> None:
    if "--files" in argv:
        write_drawings()
    data = json.loads(MANIFEST.read_text()) if MANIFEST.is_file() else {"models": {}}
    models: dict[str, dict[str, object]] = data["models"]
    for p in _own_models():
        models.setdefault(p.stem, {"file": p.name})
    version = openscad_version()
    names = [a for a in argv if not a.startswith("--")]
    for name, entry in sorted(models.items()):
        model = DIR / str(entry["file"])
        stale = entry.get("sha256") != hashlib.sha256(model.read_bytes()).hexdigest() or "stl_volume" not in entry
        if "--all" in argv or name in names or (not names and stale):
            print(f"{name}: {entry['file']}", flush=True)
            regenerate(entry, version)
            _save({name: entry})


if __name__ == "__main__":
    main(sys.argv[1:])
