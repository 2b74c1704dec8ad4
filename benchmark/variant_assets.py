"""Write the variant assets a dev round was written on, from the shared PartNet-Mobility folders and a manifest.

Rounds 30 and 31 were written blind on dev assets rewritten by :mod:`benchmark.variants` (mirrored, turned, flipped,
resting ajar, placed elsewhere): objects whose layout the agent's rules were never fitted to. The manifest names each
folder's source and the transforms applied, in order (each step is one :func:`make_variant` call)::

    python -m benchmark.variant_assets --manifest benchmark/probes/dev_round30_assets.json --assets ../shared/assets --out OUT
    python -m benchmark.probe --expect benchmark/probes/dev_round30_prompts.jsonl --assets OUT --out RUN --in-process
"""

from __future__ import annotations

import argparse
import json
import shutil
import sys
import tempfile
from pathlib import Path

from benchmark.stacks import is_stack, write_stack
from benchmark.variants import TRANSFORMS, make_variant


def write_assets(manifest: dict[str, dict[str, object]], assets: Path, out: Path) -> list[Path]:
    """Every folder of ``manifest`` written under ``out`` (``out/<folder>``); returns them."""
    written = []
    for folder, recipe in sorted(manifest.items()):
        source = assets / str(recipe["source"])
        steps = [tuple(step) for step in recipe["steps"]]  # type: ignore[attr-defined]
        unknown = [t for step in steps if not is_stack(step) for t in step if t not in TRANSFORMS]
        if unknown or not steps:
            raise ValueError(f"{folder}: unknown transforms {unknown}" if unknown else f"{folder}: no steps")
        if not (source / "mobility.urdf").is_file() and not list(source.glob("*.urdf")):
            raise FileNotFoundError(f"{folder}: source asset not found: {source}")
        target = out / folder
        with tempfile.TemporaryDirectory() as scratch:
            current = source
            for k, step in enumerate(steps):
                last = k == len(steps) - 1
                step_out = target if last else Path(scratch) / str(k) / source.name  # the folder's name keeps the object's kind
                if is_stack(step):
                    write_stack(current, step_out, step[0])
                else:
                    make_variant(current, step_out, step)
                current = step_out
        written.append(target)
    return written


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--manifest", type=Path, required=True)
    parser.add_argument("--assets", type=Path, required=True, help="the folder holding partnet/ and partnet-extra/")
    parser.add_argument("--out", type=Path, required=True)
    args = parser.parse_args(argv)
    try:
        manifest = json.loads(args.manifest.read_text())
        if args.out.exists():
            shutil.rmtree(args.out)
        written = write_assets(manifest, args.assets, args.out)
    except (OSError, ValueError, json.JSONDecodeError) as exc:
        sys.stderr.write(f"error: {exc}\n")
        return 2
    sys.stdout.write(f"wrote {len(written)} variant assets under {args.out}\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
