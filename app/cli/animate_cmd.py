"""``artimo animate``: prompt + asset -> causal.json, plan.json, trajectory.jsonl, animation.glb, report.json."""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from app.cli.export_option import add_export_option, exports_of
from app.cli.model_options import add_model_options, engine_overrides, provider_config
from app.cli.output import cache_dir, err, out


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = commands.add_parser("animate", help="animate an asset from a text prompt")
    parser.add_argument("asset", type=Path, help="asset folder or .zip")
    parser.add_argument("--urdf", default=None, metavar="NAME", help="which URDF to use when the folder or zip holds several")
    parser.add_argument("--prompt", required=True, help='what should happen, e.g. "press the pedal to open the bin"')
    parser.add_argument("--out", type=Path, required=True, help="output folder")
    add_model_options(parser)
    parser.add_argument("--critic-rounds", type=int, default=None, help="critic-actor repair rounds (default 3)")
    parser.add_argument("--fps", type=int, choices=(24, 30), default=None, help="output frame rate (default: the planner's, 30)")
    parser.add_argument("--no-collisions", action="store_true", help="skip the critic's collision checks")
    parser.add_argument("--preview", action="store_true", help="also render OUT/preview.gif of the final animation (needs EGL)")
    add_export_option(parser)
    parser.set_defaults(handler=_animate)


class _Progress:
    def on_stage(self, stage: str, progress: int) -> None:
        err(f"[{progress:3d}%] {stage}")

    def on_message(self, message: str) -> None:
        err(message)


def _animate(args: argparse.Namespace) -> int:
    from app.engine.config import EngineConfig
    from app.engine.pipeline import PipelineRequest, run_pipeline
    from app.engine.providers.registry import make_roles

    began = time.perf_counter()
    config = EngineConfig(check_collisions=not args.no_collisions, preview=args.preview, asset_cache_dir=cache_dir(args), exports=exports_of(args),
                          **engine_overrides(args))
    roles = make_roles(args.provider, provider_config(args), config)
    result = run_pipeline(
        PipelineRequest(asset=args.asset, prompt=args.prompt, max_critic_rounds=args.critic_rounds, fps=args.fps, urdf=args.urdf),
        roles=roles, config=config, out_dir=args.out, observer=_Progress(),
    )
    report = result.report
    from app.engine.offline.explain import lines

    for line in lines(report.understanding):
        out(line)
    for warning in report.warnings:
        out(f"note: {warning}")
    for role, usage in report.usage_by_role.items():
        if role != "perceiver" or usage.calls:
            cost = "" if usage.est_cost_usd is None else f", ~${usage.est_cost_usd:.4f}"
            retries = f", {usage.transport_retries} retries" if usage.transport_retries else ""
            out(f"{role:<11} {usage.calls} calls ({usage.failed_calls} failed{retries}), {usage.input_tokens}+{usage.output_tokens} tokens{cost}")
    out(f"critic: {report.final_state}")
    for kind, name in result.outputs.items():
        out(f"{kind:<11} {args.out / name}")
    out(f"done in {time.perf_counter() - began:.2f} s")
    return 0
