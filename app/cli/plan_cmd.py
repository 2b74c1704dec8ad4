"""``artimo plan``: re-plan from a Causal.json (ours or a model's) without perceiving a prompt.

The offline planner reads only the contract, so the plan made from the ``causal.json`` that
``artimo animate`` wrote is the same ``plan.json`` (tests pin it). Use it to edit what the agent
understood (a goal, an amount, an order) and run it again.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from app.cli.export_option import add_export_option, exports_of
from app.cli.output import cache_dir, err, out
from app.engine.errors import PlanValidationError


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = commands.add_parser("plan", help="re-plan an asset from a causal.json (no prompt, no model)")
    parser.add_argument("asset", type=Path, help="asset folder or .zip")
    parser.add_argument("--causal", type=Path, required=True, help="a causal.json (e.g. from artimo animate, possibly edited)")
    parser.add_argument("--out", type=Path, required=True, help="output folder")
    parser.add_argument("--critic-rounds", type=int, default=None, help="critic-actor repair rounds (default 3)")
    parser.add_argument("--fps", type=int, choices=(24, 30), default=None, help="output frame rate (default: the planner's, 30)")
    parser.add_argument("--no-collisions", action="store_true", help="skip the critic's collision checks")
    parser.add_argument("--preview", action="store_true", help="also render OUT/preview.gif (needs EGL)")
    add_export_option(parser)
    parser.set_defaults(handler=_plan)


def read_causal(path: Path):  # type: ignore[no-untyped-def]
    """A Causal.json from disk; PlanValidationError naming the field when it is not one."""
    from pydantic import ValidationError

    from app.engine.contracts.causal import CausalDocument

    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise PlanValidationError(f"cannot read {path}: {exc.strerror or exc}") from exc
    try:
        return CausalDocument.model_validate_json(text)
    except ValidationError as exc:
        issues = [f"{'.'.join(str(p) for p in e['loc']) or '(document)'}: {e['msg']}" for e in exc.errors()]
        raise PlanValidationError(f"{path} is not a valid causal document", issues=issues) from exc


def _plan(args: argparse.Namespace) -> int:
    from app.engine.config import EngineConfig
    from app.engine.offline.roles import offline_roles
    from app.engine.pipeline import PipelineRequest, run_pipeline

    began = time.perf_counter()
    document = read_causal(args.causal)
    config = EngineConfig(check_collisions=not args.no_collisions, preview=args.preview, asset_cache_dir=cache_dir(args), exports=exports_of(args))
    result = run_pipeline(PipelineRequest(asset=args.asset, prompt="", causal=document, max_critic_rounds=args.critic_rounds, fps=args.fps),
                          roles=offline_roles(), config=config, out_dir=args.out)
    for warning in result.report.warnings:
        err(f"note: {warning}")
    out(f"critic: {result.report.final_state}")
    for kind, name in result.outputs.items():
        out(f"{kind:<11} {args.out / name}")
    out(f"done in {time.perf_counter() - began:.2f} s")
    return 0
