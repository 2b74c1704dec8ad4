"""``artimo inspect``, ``artimo validate-plan``, ``artimo run-plan``."""

from __future__ import annotations

import argparse
import time
from pathlib import Path
from typing import TYPE_CHECKING, Any

from app.cli.export_option import add_export_option, exports_of
from app.cli.output import cache_dir, out, out_json
from app.engine.asset.cache import load_asset_cached
from app.engine.asset.model import ArticulatedAsset
from app.engine.asset.summary import joint_summary, scale_context
from app.engine.errors import PlanValidationError
from app.engine.plan.checks import load_json_file, validate_plan

if TYPE_CHECKING:
    from app.engine.asset.layout import JointEnds


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
    add_export_option(run)
    run.set_defaults(handler=_run)


def _urdf_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--urdf", default=None, metavar="NAME",
                        help="which URDF to use when the folder or zip holds several (its path inside, or its file name)")


def _fmt(value: float | None) -> str:
    return "-" if value is None else f"{value:.4g}"


def _ends(ends: JointEnds) -> str:
    """"closed/rest at lower (0), open at upper (1.57)" from the geometry's reading of a joint's range."""
    def at(end: str | None, value: float | None) -> str:
        return f"at {end} ({_fmt(value)})" if end not in (None, "between") else f"at {_fmt(value)}"

    if ends.closed is None or ends.open is None:
        if ends.type == "continuous":
            return f"rest {_fmt(ends.rest)}, turns freely"
        return f"rest {at(ends.rest_end, ends.rest)}; the geometry does not tell closed from open"
    if abs(ends.rest - ends.closed) < 1e-9:
        return f"closed/rest {at(ends.closed_end, ends.closed)}, open {at(ends.open_end, ends.open)}"
    if abs(ends.rest - ends.open) < 1e-9:
        return f"open/rest {at(ends.open_end, ends.open)}, closed {at(ends.closed_end, ends.closed)}"
    return f"rest {at(ends.rest_end, ends.rest)}, closed {at(ends.closed_end, ends.closed)}, open {at(ends.open_end, ends.open)}"


CONVENTION = " by convention: nothing on it shows where it faces"


def _inspect(args: argparse.Namespace) -> int:
    from app.engine.asset.layout import asset_layout, direction_name

    asset = load_asset_cached(args.asset, cache_dir(args), urdf=args.urdf)
    scale = scale_context(asset)
    layout = asset_layout(asset)
    if args.json:
        out_json({"joints": [j.model_dump() for j in joint_summary(asset)], "scale": scale.model_dump(), "layout": layout.model_dump()})
        return 0
    out(f"asset {asset.name}  ({asset.urdf_file}, root link {asset.root_link})")
    out(f"size {' x '.join(f'{v:.3f}' for v in scale.object_bbox_extents_m)} m, diagonal {scale.object_diag_m:.3f} m; "
        f"front faces {direction_name(layout.front)}{CONVENTION if layout.front_by_convention else f', shown by {layout.front_shown_by}'} "
        "(left/right below are as seen from the front)")
    ends = {e.joint: e for e in layout.joints}
    out("\njoints:")
    for name in asset.joint_order:
        joint = asset.joints[name]
        limits = f"[{_fmt(joint.lower)}, {_fmt(joint.upper)}]" if joint.bounded else ("free" if joint.type == "continuous" else "")
        axis = "" if not joint.movable else " axis " + " ".join(f"{v:+.3f}" for v in joint.axis)
        mimic = f" mimics {joint.mimic.joint} x{joint.mimic.multiplier:g}{joint.mimic.offset:+g}" if joint.mimic else ""
        out(f"  {name:<20} {joint.type:<10} {joint.parent} -> {joint.child}{axis} {limits}{mimic}")
        if name in ends:
            out(f"  {'':<20} {_ends(ends[name])}")
    places = {p.link: p for p in layout.parts}
    out("\nlinks:")
    for name in asset.link_order:
        link = asset.links[name]
        faces = sum(len(p.faces) for p in link.parts)
        size = scale.link_bbox_extents_m.get(name)
        dims = " x ".join(f"{v:.3f}" for v in size) if size else "no geometry"
        place = places.get(name)
        where = f"  {place.vertical}, {place.side}, {place.depth}" if place else ""
        shown = place.name if place else name
        out(f"  {shown:<32} ({link.semantics.source}) {len(link.parts)} parts, {faces} faces, {dims}{where}")
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
    exports = exports_of(args)
    asset, plan = _load(args)
    report = run_plan(asset, plan, args.out, preview=args.preview, exports=exports)
    for warning in report.warnings + report.events:
        out(f"note: {warning}")
    for kind, name in report.outputs.items():
        out(f"{kind:<11} {args.out / name}")
    out(f"done in {time.perf_counter() - began:.2f} s")
    return 0
