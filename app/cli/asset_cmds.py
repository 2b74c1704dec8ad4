"""``artimo inspect``, ``artimo validate-plan``, ``artimo run-plan``."""

from __future__ import annotations

import argparse
import time
from pathlib import Path
from typing import Any

from app.cli.output import cache_dir, out, out_json
from app.engine.asset.cache import load_asset_cached
from app.engine.asset.model import ArticulatedAsset
from app.engine.asset.summary import joint_summary, scale_context
from app.engine.errors import PlanValidationError
from app.engine.plan.checks import load_json_file, validate_plan


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    inspect = commands.add_parser("inspect", help="show joints, limits, links, semantics and scale of an asset")
    inspect.add_argument("asset", type=Path, help="asset folder or .zip")
    _urdf_option(inspect)
    inspect.add_argument("--json", action="store_true", help="print the joint summary and scale context as JSON")
    inspect.set_defaults(handler=_inspect)

    validate = commands.add_parser("validate-plan", help="check a Plan.json against an asset")
    validate.add_argument("asset", type=Path)
    _urdf_option(validate)
    validate.add_argument("--plan", type=Path, required=True)
    validate.set_defaults(handler=_validate)

    run = commands.add_parser("run-plan", help="execute a Plan.json and export trajectory.jsonl + animation.glb")
    run.add_argument("asset", type=Path)
    _urdf_option(run)
    run.add_argument("--plan", type=Path, required=True)
    run.add_argument("--out", type=Path, required=True, help="output folder")
    run.add_argument("--preview", action="store_true", help="also render OUT/preview.gif (needs EGL)")
    run.set_defaults(handler=_run)


def _urdf_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--urdf", default=None, metavar="NAME",
                        help="which URDF to use when the folder or zip holds several (its path inside, or its file name)")


def _fmt(value: float | None) -> str:
    return "-" if value is None else f"{value:.4g}"


def _inspect(args: argparse.Namespace) -> int:
    asset = load_asset_cached(args.asset, cache_dir(args), urdf=args.urdf)
    scale = scale_context(asset)
    if args.json:
        out_json({"joints": [j.model_dump() for j in joint_summary(asset)], "scale": scale.model_dump()})
        return 0
    out(f"asset {asset.name}  ({asset.urdf_file}, root link {asset.root_link})")
    out(f"size {' x '.join(f'{v:.3f}' for v in scale.object_bbox_extents_m)} m, diagonal {scale.object_diag_m:.3f} m")
    out("\njoints:")
    for name in asset.joint_order:
        joint = asset.joints[name]
        limits = f"[{_fmt(joint.lower)}, {_fmt(joint.upper)}]" if joint.bounded else ("free" if joint.type == "continuous" else "")
        axis = "" if not joint.movable else " axis " + " ".join(f"{v:+.3f}" for v in joint.axis)
        mimic = f" mimics {joint.mimic.joint} x{joint.mimic.multiplier:g}{joint.mimic.offset:+g}" if joint.mimic else ""
        out(f"  {name:<20} {joint.type:<10} {joint.parent} -> {joint.child}{axis} {limits}{mimic}")
    out("\nlinks:")
    for name in asset.link_order:
        link = asset.links[name]
        faces = sum(len(p.faces) for p in link.parts)
        label = link.semantics.label or "-"
        size = scale.link_bbox_extents_m.get(name)
        dims = " x ".join(f"{v:.3f}" for v in size) if size else "no geometry"
        out(f"  {name:<20} label {label:<18} ({link.semantics.source}) {len(link.parts)} parts, {faces} faces, {dims}")
    for warning in asset.warnings:
        out(f"warning: {warning}")
    return 0


def _read_plan(path: Path) -> dict[str, Any]:
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise PlanValidationError(f"cannot read plan {path}", issues=[str(exc)]) from exc
    return load_json_file(text, f"plan {path.name}")


def _load(args: argparse.Namespace) -> tuple[ArticulatedAsset, dict[str, Any]]:
    return load_asset_cached(args.asset, cache_dir(args), urdf=args.urdf), _read_plan(args.plan)


def _validate(args: argparse.Namespace) -> int:
    asset, plan = _load(args)
    checked = validate_plan(plan, asset)
    out(f"plan {args.plan} is valid for {asset.name}")
    for warning in checked.warnings:
        out(f"  warning: {warning}")
    return 0


def _run(args: argparse.Namespace) -> int:
    from app.engine.run import run_plan

    began = time.perf_counter()
    asset, plan = _load(args)
    report = run_plan(asset, plan, args.out, preview=args.preview)
    for warning in report.warnings + report.events:
        out(f"note: {warning}")
    for kind, name in report.outputs.items():
        out(f"{kind:<11} {args.out / name}")
    out(f"done in {time.perf_counter() - began:.2f} s")
    return 0
