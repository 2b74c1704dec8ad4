"""``artimo animate``: prompt + asset -> causal.json, plan.json, trajectory.jsonl, animation.glb, report.json."""

from __future__ import annotations

import argparse
import os
import time
from pathlib import Path

from app.cli.output import cache_dir, err, out
from app.engine.errors import ProviderError


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = commands.add_parser("animate", help="animate an asset from a text prompt")
    parser.add_argument("asset", type=Path, help="asset folder or .zip")
    parser.add_argument("--urdf", default=None, metavar="NAME", help="which URDF to use when the folder or zip holds several")
    parser.add_argument("--prompt", required=True, help='what should happen, e.g. "press the pedal to open the bin"')
    parser.add_argument("--out", type=Path, required=True, help="output folder")
    parser.add_argument("--provider", default="offline", help="offline (default, no API key), openai (any OpenAI-compatible server) or gemini")
    parser.add_argument("--model", action="append", default=[], metavar="ROLE=NAME",
                        help="model per role, e.g. --model perceiver=gpt-4.1 --model critic=geometric (repeatable)")
    parser.add_argument("--base-url", default=None, help="provider endpoint (default: $OPENAI_BASE_URL / $GEMINI_BASE_URL or the public API)")
    parser.add_argument("--critic-rounds", type=int, default=None, help="critic-actor repair rounds (default 3)")
    parser.add_argument("--fps", type=int, choices=(24, 30), default=None, help="output frame rate (default: the planner's, 30)")
    parser.add_argument("--render", action="store_true", help="also render reference/overlay images into OUT/images")
    parser.add_argument("--no-collisions", action="store_true", help="skip the critic's collision checks")
    parser.add_argument("--preview", action="store_true", help="also render OUT/preview.gif of the final animation (needs EGL)")
    parser.set_defaults(handler=_animate)


class _Progress:
    def on_stage(self, stage: str, progress: int) -> None:
        err(f"[{progress:3d}%] {stage}")

    def on_message(self, message: str) -> None:
        err(message)


def _provider_config(args: argparse.Namespace):  # type: ignore[no-untyped-def]
    """API key and endpoint from the environment (the CLI is an entry point; the engine never reads it)."""
    from app.engine.providers.registry import ProviderConfig

    prefix = {"openai": "OPENAI", "gemini": "GEMINI"}.get(args.provider)
    models = []
    for item in args.model:
        role, _, name = item.partition("=")
        if role not in ("perceiver", "planner", "critic") or not name:
            raise ProviderError(f"--model expects ROLE=NAME with ROLE perceiver, planner or critic, got {item!r}")
        models.append((role, name))
    if prefix is None:
        return ProviderConfig(models=tuple(models))
    return ProviderConfig(api_key=os.environ.get(f"{prefix}_API_KEY"), base_url=args.base_url or os.environ.get(f"{prefix}_BASE_URL"), models=tuple(models))


def _animate(args: argparse.Namespace) -> int:
    from app.engine.config import EngineConfig
    from app.engine.pipeline import PipelineRequest, run_pipeline
    from app.engine.providers.registry import make_roles

    began = time.perf_counter()
    config = EngineConfig(render_images=args.render, check_collisions=not args.no_collisions, preview=args.preview,
                          asset_cache_dir=cache_dir(args))
    roles = make_roles(args.provider, _provider_config(args), config)
    result = run_pipeline(
        PipelineRequest(asset=args.asset, prompt=args.prompt, max_critic_rounds=args.critic_rounds, fps=args.fps, urdf=args.urdf),
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
