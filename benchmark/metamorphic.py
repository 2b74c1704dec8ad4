"""Metamorphic probe: the same object, written down differently, must animate the same.

For every asset an expectations file uses, writes a *variant* whose shape and motion are those of
the original but whose URDF says them differently, rewrites each expectation to match, runs the
offline agent on originals and variants (in process) and lists every prompt whose outcome changed.
The transforms (``--transforms``, comma-separated, applied in this order):

- ``flip``: every revolute, prismatic and continuous joint's axis negated and its limits mirrored
  (a joint value ``q`` becomes ``-q``; mimic offsets follow). PartNet-Mobility writes either sign.
- ``rename``: ``link_N`` / ``joint_N`` numbered backwards (``semantics.txt`` follows), so a choice
  that leans on the numbering shows.
- ``reorder``: ``<link>`` and ``<joint>`` elements in reverse file order.
- ``shift``: every movable joint's frame slid 5 cm along its own axis, its child's contents slid back (the same
  hinge line, another origin).
- ``move``: the whole object placed 1.3 m, -0.7 m, 0.25 m away from the URDF's origin.
- ``yaw``: the whole object turned 90 degrees about up (expected base translations turn with it).
  Not a pure re-encoding: where nothing on the object says where its front is, the agent's
  conventional front does not turn, so its results are listed apart.
- ``mirror``: the object's mirror image across the URDF's XZ plane, and each prompt with its sides and senses of turning
  swapped ("left" <-> "right", "clockwise" <-> "counterclockwise"), so the expectation stays (its base translations
  mirrored). Rows where "left" or "right" may mean something else ("right away", "left open") are left out, and so are
  rows that lean on a convention a mirror does not keep (a mixer's hot side, a thread's hand, the way a knob turns on).
- ``ajar``: every door, lid, drawer, window and screen that rests at a limit rests 30% of the way to
  the other (assets are modelled shut or open). Only rows that take such parts to one of their limits
  ("open the door", "shut the lid") are kept: they mean the same pose whatever the part rests at.

A prompt right on the original and wrong on a pure re-encoding is a bug: the agent read the
encoding, not the object. Prompts naming ``link_``/``joint_`` are skipped under ``rename``::

    python -m benchmark.metamorphic --expect benchmark/probes/dev_round29_prompts.jsonl --assets ../shared/assets --out OUT
    python -m benchmark.metamorphic --expect FILE --assets ROOT --out OUT --transforms yaw

Writes OUT/original and OUT/variant (probe runs), OUT/assets (the variants), OUT/expect.jsonl and
OUT/diff.json; prints the changed prompts and a one-line count. Exit status 0 (it measures).
"""

from __future__ import annotations

import argparse
import json
import math
import re
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from benchmark.probe import judge, run_in_process
from benchmark.variants import PURE, TRANSFORMS, Mapping, make_variant, rpy_matrix

ROUNDING = 1e-9
"""Slack on a shifted range's ends: a limit moved by an offset and written back is off by a last bit or so."""


def _spec(spec: dict[str, Any], joint: str, m: Mapping) -> dict[str, Any]:
    out = dict(spec)
    sign = m.sign(joint)
    for key in ("final", "peak"):
        if key in out:
            out[key] = m.value(joint, out[key])
    if "delta" in out:
        out["delta"] = sign * out["delta"]
    if "final_range" in out:
        lo, hi = sorted((m.value(joint, out["final_range"][0]), m.value(joint, out["final_range"][1])))
        out["final_range"] = [lo - ROUNDING, hi + ROUNDING] if joint in m.offsets else [lo, hi]
    return out


def _joints(group: dict[str, Any], m: Mapping) -> dict[str, Any]:
    return {m.name(n): _spec(s, n, m) for n, s in group.items()}


def _token(token: str, m: Mapping) -> str:
    name, ret = (token[:-4], "@ret") if token.endswith("@ret") else (token, "")
    return m.name(name) + ret


def transform_expect(expect: dict[str, Any], m: Mapping) -> dict[str, Any]:
    """The expectation ``expect`` of the original, said of the variant."""
    out = dict(expect)
    if "joints" in out:
        out["joints"] = _joints(out["joints"], m)
    if "any_of" in out:
        out["any_of"] = [_joints(g, m) for g in out["any_of"]]
    if "optional" in out:
        out["optional"] = [m.name(n) for n in out["optional"]]
    if "order" in out:
        out["order"] = [_token(t, m) for t in out["order"]]
    if "hold" in out:
        out["hold"] = {**out["hold"], "joint": m.name(out["hold"]["joint"])}
    base = out.get("base")
    if base and "translation" in base and m.mirrored:
        x, y, z = (float(v) for v in base["translation"])
        base = out["base"] = {**base, "translation": [x, -y, z]}
    if base and "translation" in base and m.yaw_deg:
        turn = rpy_matrix(np.array([0.0, 0.0, math.radians(m.yaw_deg)]))
        out["base"] = {**base, "translation": [round(float(v), 6) for v in turn @ np.array(base["translation"], dtype=float)]}
    return out


def comparable(row: dict[str, Any], transforms: tuple[str, ...]) -> bool:
    """Rows whose expectation can be carried over: no part named by its link/joint name under
    ``rename``, no whole-object turn under ``move``, no 'FULL' order token (the judge picks it by the sign of a final value)."""
    if "rename" in transforms and re.search(r"\b(link|joint)_\d", row["prompt"]):
        return False
    if "move" in transforms and "base" in row.get("expect", {}) and TURNS.search(row["prompt"].lower()):
        return False
    if "mirror" in transforms and (NOT_A_SIDE.search(row["prompt"]) or HANDED.search(row["prompt"])):
        return False  # turned in place about its own centre: away from the URDF's origin, that is a translation too
    return "FULL" not in row.get("expect", {}).get("order", [])


SWAPPED = {"left": "right", "right": "left", "leftmost": "rightmost", "rightmost": "leftmost", "left-hand": "right-hand",
           "right-hand": "left-hand", "lefthand": "righthand", "righthand": "lefthand", "clockwise": "counterclockwise",
           "counterclockwise": "clockwise", "counter-clockwise": "clockwise", "anticlockwise": "clockwise", "anti-clockwise": "clockwise",
           "cw": "ccw", "ccw": "cw", "counter clockwise": "clockwise", "anti clockwise": "clockwise", "rigth": "left", "rihgt": "left",
           "lefft": "right", "clockwsie": "counterclockwise", "anticlokwise": "clockwise"}
SIDE_WORDS = re.compile(r"\b(" + "|".join(sorted(map(re.escape, SWAPPED), key=len, reverse=True)) + r")\b", re.IGNORECASE)
NOT_A_SIDE = re.compile(r"\bright (away|now|after|before|there|here|then|up to|at the|on|into|in|back|through|angle|below|above|under|over|"
                        r"next|beside|by|behind|against|this|the|that|it)\b|\bright-angle|\ball right\b|\bthat's right\b"
                        r"|\b(is|was|be|been|are|were|it|them|gets?|got|stays?|remains?|keep|kept|someone|somebody|i|you|we|they|he|she|who) left\b|\bleft (open|ajar|shut|closed|alone|as|in place|"
                        r"where|untouched|over|behind|there|standing|sitting|hanging|sticking|resting)\b|\bleft[-_ ]?over", re.IGNORECASE)
"""'right' and 'left' that are no side ("right away", "the lid left open"): such rows are left out under ``mirror``."""
HANDED = re.compile(r"\b(hot|cold|warm|warmer|colder|hotter|hottest|coldest|tighten\w*|loosen\w*|unscrew\w*|screw\w*|unlock\w*|lock\w*|"
                    r"cap|bottle|o'?\s?clock|keypad|key pad|number pad|code|digits?|keys?)\b|\d\s*[-,]\s*\d"
                    r"|\b(turn|switch|twist|crank|dial|rotate|put)\b[^.,;:]*\b(on|off|open|shut|closed)\b", re.IGNORECASE)
"""Conventions a mirror image does not keep: a mixer's hot side, a thread's hand, the way a knob or valve turns on, off,
open or shut, a clock face, a keypad's layout. The variant's true answer keeps the convention, not the reflection, so such rows are left out."""


def mirror_words(prompt: str) -> str:
    """The prompt said of the mirror image: sides and senses of turning swapped, each word's capitals kept."""
    def swap(match: re.Match[str]) -> str:
        word = match.group(0)
        new = SWAPPED[word.lower()]
        return new.capitalize() if word[0].isupper() else new
    return SIDE_WORDS.sub(swap, prompt)


TURNS = re.compile(r"\b(turn|rotat|spin|angle|around|round|swivel|twist|pivot|fac(e|ing)|quarter)")


LIMIT_TOL = 1e-3


def _at_a_limit(spec: dict[str, Any], limits: tuple[float, float]) -> bool:
    """A final value that is one of the joint's limits ("open it", "shut it"): the same pose whatever the part rests at."""
    if set(spec) - {"final", "final_range", "tol", "final_tol"}:
        return False
    if "final_range" in spec:
        lo, hi = spec["final_range"]
        return any(lo - LIMIT_TOL <= limit <= hi + LIMIT_TOL for limit in limits)
    return "final" in spec and any(abs(spec["final"] - limit) <= spec.get("tol", 0.0) + LIMIT_TOL for limit in limits)


def rests_elsewhere_alike(row: dict[str, Any], m: Mapping) -> bool:
    """Under ``ajar``: a row that asks only for parts set resting part-way, each taken to one of its limits, and
    refuses nothing; what it asks means the same pose whether the part rested shut or ajar."""
    expect = row["expect"]
    joints = expect.get("joints", {})
    if expect.get("refuse") or "any_of" in expect or "hold" in expect or "base" in expect or not joints:
        return False
    return all(n in m.limits and _at_a_limit(spec, m.limits[n]) for n, spec in joints.items())


def build(expect_files: list[Path], assets: Path, out: Path, transforms: tuple[str, ...]) -> tuple[Path, Path]:
    """Write OUT/original.jsonl, OUT/expect.jsonl (the variants') and OUT/assets; return both files."""
    rows = [json.loads(line) for path in expect_files for line in path.read_text().splitlines() if line.strip()]
    rows = [r for r in rows if comparable(r, transforms)]
    mappings: dict[str, Mapping] = {}
    for asset_dir in sorted({r["asset_dir"] for r in rows}):
        mappings[asset_dir] = make_variant(assets / asset_dir, out / "assets" / asset_dir, transforms)
    if "ajar" in transforms:
        rows = [r for r in rows if rests_elsewhere_alike(r, mappings[r["asset_dir"]])]
    original, variant = out / "original.jsonl", out / "expect.jsonl"
    original.write_text("".join(json.dumps(r) + "\n" for r in rows))
    said = mirror_words if "mirror" in transforms else str
    variant.write_text("".join(json.dumps({**r, "prompt": said(r["prompt"]), "expect": transform_expect(r["expect"], mappings[r["asset_dir"]])}) + "\n"
                               for r in rows))
    return original, variant


def _judge(out: Path, expect: Path, assets: Path) -> dict[str, dict[str, Any]]:
    return {c["id"]: c for c in judge(out, expect, assets)["cases"]}


def compare(before: dict[str, dict[str, Any]], after: dict[str, dict[str, Any]]) -> list[dict[str, Any]]:
    """Every prompt whose outcome on the variant differs from the original's."""
    return [{"id": i, "prompt": before[i]["prompt"], "original": before[i]["outcome"], "variant": after[i]["outcome"],
             "errors": after[i]["errors"] or before[i]["errors"]}
            for i in before if i in after and before[i]["outcome"] != after[i]["outcome"]]


def main(argv: list[str] | None = None, runner: Callable[[Path, Path, Path], None] = run_in_process) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--expect", type=Path, action="append", required=True, help="expectations file (repeatable)")
    parser.add_argument("--assets", type=Path, required=True)
    parser.add_argument("--out", type=Path, required=True)
    parser.add_argument("--transforms", default=",".join(PURE), help=f"comma-separated, of {', '.join(TRANSFORMS)}")
    args = parser.parse_args(argv)
    transforms = tuple(t.strip() for t in args.transforms.split(",") if t.strip())
    unknown = [t for t in transforms if t not in TRANSFORMS]
    if unknown or not transforms:
        sys.stderr.write(f"error: unknown transform(s) {unknown}; choose from {', '.join(TRANSFORMS)}\n")
        return 2
    args.out.mkdir(parents=True, exist_ok=True)
    original, variant = build(args.expect, args.assets, args.out, transforms)
    runner(original, args.out / "original", args.assets)
    runner(variant, args.out / "variant", args.out / "assets")
    before = _judge(args.out / "original", original, args.assets)
    after = _judge(args.out / "variant", variant, args.out / "assets")
    changed = compare(before, after)
    (args.out / "diff.json").write_text(json.dumps({"transforms": transforms, "changed": changed}, indent=1))
    for row in changed:
        sys.stdout.write(f"{row['id']}: {row['original']} -> {row['variant']} | {row['prompt']}\n     {'; '.join(row['errors'])[:300]}\n")
    right = sum(c["outcome"] == "right" for c in before.values())
    lost = sum(r["original"] == "right" for r in changed)
    sys.stdout.write(f"{len(before)} prompts, transforms {','.join(transforms)}: {right} right on the originals; "
                     f"{len(changed)} changed outcome ({lost} right -> wrong, {len(changed) - lost} other)\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
