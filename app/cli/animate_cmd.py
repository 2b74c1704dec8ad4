"""``artimo animate``: prompt + asset -> causal.json, plan.json, trajectory.jsonl, animation.glb, report.json."""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from app.cli.output import cache_dir, err, out


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = commands.add_parser("animate", help="animate an asset from a text prompt")
    parser.add_argument("asset", type=Path, help="asset folder or .zip")
    parser.add_argument("--prompt", required=True, help='what should happen, e.g. "press the pedal to open the bin"')
    parser.add_argument("--out", type=Path, required=True, help="output folder")
    parser.add_argument("--provider", default="offline", help="offline (default, no API key) or a model provider")
    parser.add_argument("--critic-rounds", type=int, default=None, help="critic-actor repair rounds (default 3)")
    parser.add_argument("--render", action="store_true", help="also render reference/overlay images into OUT/images")
    parser.add_argument("--no-collisions", action="store_true", help="skip the critic's collision checks")
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
    config = EngineConfig(render_images=args.render, check_collisions=not args.no_collisions, asset_cache_dir=cache_dir(args))
    roles = make_roles(args.provider)
    result = run_pipeline(
        PipelineRequest(asset=args.asset, prompt=args.prompt, max_critic_rounds=args.critic_rounds),
        roles=roles, config=config, out_dir=args.out, observer=_Progress(),
    )
    report = result.report
    for warning in report.warnings:
        out(f"note: {warning}")
    out(f"critic: {report.final_state}")
    for kind, name in result.outputs.items():
        out(f"{kind:<11} {args.out / name}")
    out(f"done in {time.perf_counter() - began:.2f} s")
    return 0
