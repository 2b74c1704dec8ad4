"""``artimo bench critic``: how often the critic detects an injected failure, and whether the loop repairs it.

For each case of a SPEC §5 case file and each injectable class (:mod:`critic_injection`),
the corrupted plan goes through the same critic-actor loop the pipeline uses (up to
``max_rounds`` repairs). **Detected**: round 0's diagnosis names the injected code on the
injected joint. **Repaired**: the loop ended with the critic accepting the plan and the
case's P_gIoU (SPEC §5/§6, against the ground truth) is back within ``REPAIR_TOLERANCE``
of the correct plan's; the mean P_gIoU before and after the loop is given per class too. The correct plan
itself is also shown to the critic once per case (false alarms are counted under
``clean``). The geometric critic is the default; a model critic is used when a provider
and critic model are given (its failures count as misses, with the error recorded).
"""

from __future__ import annotations

import asyncio
import logging
import multiprocessing
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from app.engine.agents.loop import refine
from app.engine.agents.roles import Context, Critic
from app.engine.asset.cache import load_asset_cached
from app.engine.asset.model import ArticulatedAsset
from app.engine.asset.summary import joint_summary, scale_context
from app.engine.config import EngineConfig, FallbackPolicy
from app.engine.errors import EngineError
from app.engine.execute.executor import execute
from app.engine.execute.trajectory import Trajectory
from app.engine.metrics.annotation import Case
from app.engine.metrics.compiler import GroundTruth, compile_case
from app.engine.metrics.geometry import AssetGeometry, build_geometry
from app.engine.metrics.scoring import score_case
from app.engine.metrics.sequence import trajectory_sequence
from app.engine.providers.registry import OFFLINE, ProviderConfig, make_roles
from benchmark.cases import read_cases
from benchmark.critic_injection import CLASSES, expectations_from_case, inject

logger = logging.getLogger(__name__)

REPAIR_TOLERANCE = 0.01
SCORE = "P_gIoU"


@dataclass(frozen=True)
class CriticJob:
    case: Case
    asset_dir: str
    provider: str
    provider_config: ProviderConfig
    config: EngineConfig
    max_rounds: int
    classes: tuple[str, ...]


def _score(asset: ArticulatedAsset, geometry: AssetGeometry, truth: GroundTruth, trajectory: Trajectory) -> float:
    return round(float(score_case(asset, geometry, truth, trajectory_sequence(asset, trajectory, "critic-bench")).values[SCORE]), 6)


def critic_label(provider: str, provider_config: ProviderConfig) -> str:
    models = dict(provider_config.models)
    if provider == OFFLINE or models.get("critic", "") == "geometric":
        return "geometric"
    return f"{provider}:{models.get('critic', 'default')}"


async def _one_case(job: CriticJob) -> list[dict[str, Any]]:
    asset = load_asset_cached(Path(job.asset_dir), job.config.asset_cache_dir)
    truth = compile_case(job.case, asset)
    expected = expectations_from_case(job.case, asset)
    geometry = build_geometry(asset)
    config = job.config.model_copy(update={"fallback": FallbackPolicy(critic="fail")})
    roles = make_roles(job.provider, job.provider_config, config)
    render = bool(roles.vision and "critic" in roles.vision) if config.render_images is None else bool(config.render_images)
    context = Context(asset=asset, prompt=job.case.prompt, joint_summary=joint_summary(asset), scale=scale_context(asset), config=config, render=render)
    correct = _score(asset, geometry, truth, truth.trajectory)
    rows: list[dict[str, Any]] = []
    try:
        critic: Critic = roles.critic
        clean = await refine(context, expected, truth.plan, critic, max_rounds=0)
        flagged = [f"{i.code}:{i.joint}" for r in clean.rounds for i in r.issues]
        rows.append({"case_id": job.case.case_id, "class": "clean", "flagged": flagged, "false_alarm": bool(flagged),
                     "error": next((r.error for r in clean.rounds if r.error), None)})
        for code in job.classes:
            injection = inject(code, truth, asset, expected)
            row: dict[str, Any] = {"case_id": job.case.case_id, "class": code, "applicable": injection is not None}
            if injection is not None:
                row.update(joint=injection.joint, segment_index=injection.segment_index, injection=injection.description)
                injected = _score(asset, geometry, truth, execute(injection.plan, asset))
                refined = await refine(context, expected, injection.plan, critic, max_rounds=job.max_rounds)
                first = refined.rounds[0] if refined.rounds else None
                issues = list(first.issues) if first else []
                row.update(
                    detected=any(i.code == code and i.joint == injection.joint for i in issues),
                    flagged=[f"{i.code}:{i.joint}" for i in issues], error=first.error if first else None,
                    score_correct=correct, score_injected=injected, score_repaired=_score(asset, geometry, truth, refined.trajectory),
                    final_state=refined.state, rounds=len(refined.rounds),
                )
                row["repaired"] = refined.state == "accepted" and row["score_repaired"] >= correct - REPAIR_TOLERANCE
            rows.append(row)
    finally:
        await roles.aclose()
    return rows


def run_case(job: CriticJob) -> list[dict[str, Any]]:
    """Every injection of one case (never raises for engine failures: they are recorded)."""
    try:
        return asyncio.run(_one_case(job))
    except EngineError as exc:
        logger.warning("case %s: %s", job.case.case_id, exc)
        return [{"case_id": job.case.case_id, "class": "case_error", "error": f"{type(exc).__name__}: {exc}"}]


def summarize(rows: list[dict[str, Any]], classes: tuple[str, ...]) -> dict[str, dict[str, Any]]:
    """Per class: ``n`` injections, ``detected``, detection ``rate`` and ``repaired`` (the names the output keeps)."""
    table: dict[str, dict[str, Any]] = {}
    for code in classes:
        made = [r for r in rows if r["class"] == code and r.get("applicable")]
        detected = sum(bool(r["detected"]) for r in made)
        table[code] = {"n": len(made), "detected": detected, "rate": round(detected / len(made), 4) if made else 0.0,
                       "repaired": sum(bool(r["repaired"]) for r in made),
                       "mean_score_injected": round(sum(r["score_injected"] for r in made) / len(made), 4) if made else None,
                       "mean_score_repaired": round(sum(r["score_repaired"] for r in made) / len(made), 4) if made else None}
    return table


def critic_bench(
    cases_file: Path, assets_root: Path, *, provider: str = OFFLINE, provider_config: ProviderConfig | None = None,
    config: EngineConfig | None = None, max_rounds: int = 3, classes: tuple[str, ...] = CLASSES, jobs: int = 1,
) -> dict[str, Any]:
    """Run every injection of every case; returns ``{"critic", "classes", "cases", "clean", "settings"}``."""
    provider_config = provider_config or ProviderConfig()
    work = [CriticJob(case, str(assets_root / case.asset), provider, provider_config, config or EngineConfig(), max_rounds, classes)
            for case in read_cases(cases_file)]
    if jobs <= 1:
        results = [run_case(job) for job in work]
    else:
        with ProcessPoolExecutor(max_workers=jobs, mp_context=multiprocessing.get_context("spawn")) as pool:
            results = list(pool.map(run_case, work))
    rows = [row for result in results for row in result]
    clean = [r for r in rows if r["class"] == "clean"]
    return {
        "critic": critic_label(provider, provider_config),
        "classes": summarize(rows, classes),
        "cases": [r for r in rows if r["class"] != "clean"],
        "clean": {"n": len(clean), "false_alarms": sum(bool(r["false_alarm"]) for r in clean),
                  "flagged": {r["case_id"]: r["flagged"] for r in clean if r["flagged"]}},
        "settings": {"cases": str(cases_file), "max_rounds": max_rounds, "repair_tolerance": REPAIR_TOLERANCE, "score": SCORE},
    }


def table_lines(document: dict[str, Any]) -> list[str]:
    """The per-class table as text lines."""
    lines = [f"critic: {document['critic']}", f"{'class':<24} {'n':>4} {'detected':>9} {'rate':>7} {'repaired':>9}  {SCORE} injected -> repaired"]
    total_n = total_d = total_r = 0
    for code, row in document["classes"].items():
        scores = f"  {row['mean_score_injected']:.3f} -> {row['mean_score_repaired']:.3f}" if row["n"] else ""
        lines.append(f"{code:<24} {row['n']:>4} {row['detected']:>9} {row['rate']:>7.1%} {row['repaired']:>9}{scores}")
        total_n, total_d, total_r = total_n + row["n"], total_d + row["detected"], total_r + row["repaired"]
    lines.append(f"{'overall':<24} {total_n:>4} {total_d:>9} {(total_d / total_n if total_n else 0.0):>7.1%} {total_r:>9}")
    clean = document["clean"]
    lines.append(f"correct plans flagged: {clean['false_alarms']}/{clean['n']}")
    return lines
