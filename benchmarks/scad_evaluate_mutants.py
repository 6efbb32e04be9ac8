"""Mutated programs of tests/data/scad_eval (characters deleted, inserted, copied) that the
in-process evaluator (isocsg.openscad.evaluate) accepts, against the openscad program's export.

    PYTHONPATH=$PWD python benchmarks/scad_evaluate_mutants.py [count] [seed]

Each accepted mutant must give the program's tree call for call and float for float (a mutant
the program rejects as a syntax error is a mismatch too). Prints every mismatch and the counts.
"""

from __future__ import annotations

import random
import sys
import tempfile
from pathlib import Path

from isocsg.openscad.evaluate import evaluate_scad
from isocsg.openscad.parser import parse_csg
from isocsg.openscad.program import scad_to_csg

sys.path.insert(0, str(Path(__file__).resolve().parent))
from scad_evaluate_corpus import same_trees  # noqa: E402

DATA = Path(__file__).resolve().parent.parent / "tests" / "data" / "scad_eval"


def mutate(text: str, rng: random.Random) -> str:
    for _ in range(rng.randint(1, 3)):
        i = rng.randrange(len(text))
        r = rng.random()
        if r < 0.4:
            text = text[:i] + text[i + rng.randint(1, 3):]
        elif r < 0.8:
            text = text[:i] + rng.choice("()[]{},;=+-*/%^!<>?:.0123456789") + text[i:]
        else:
            j = rng.randrange(len(text))
            text = text[:i] + text[j:j + 8] + text[i:]
    return text


def main(count: int, seed: int) -> int:
    texts = [p.read_text() for p in sorted(DATA.glob("*.scad")) if p.stem != "color_names"]
    rng = random.Random(seed)
    accepted = tried = bad = 0
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "mutant.scad"
        while accepted < count:
            text = mutate(rng.choice(texts), rng)
            tried += 1
            mine = evaluate_scad(text)
            if mine is None:
                continue
            accepted += 1
            path.write_text(text)
            try:
                diff = same_trees(mine, parse_csg(scad_to_csg(path)))
            except Exception as exc:  # noqa: BLE001 (reported, not hidden)
                diff = f"openscad: {exc}"
            if diff is not None:
                bad += 1
                print(f"MISMATCH {diff[:300]}\n{text!r}\n")
    print(f"{accepted} of {tried} mutants accepted, {bad} mismatches")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(int(sys.argv[1]) if len(sys.argv) > 1 else 200, int(sys.argv[2]) if len(sys.argv) > 2 else 0))
