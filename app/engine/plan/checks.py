"""Validate Causal.json / Plan.json documents, alone and against an asset.

Every problem is reported with the path of the offending field
(``timeline[2].controls[0].joint: ...``); all problems are collected before raising.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from typing import Any, TypeVar

from pydantic import BaseModel, ValidationError

from app.engine.asset.model import ArticulatedAsset
from app.engine.contracts.causal import CausalDocument
from app.engine.errors import ExpressionError, PlanValidationError
from app.engine.plan.expr import Limits, evaluate_expr
from app.engine.plan.schema import JOINT_CONTROLS, JointPosition, Plan

Model = TypeVar("Model", bound=BaseModel)
TARGET_TOLERANCE = 1e-6


@dataclass(frozen=True)
class Checked:
    """A validated document plus the warnings it raised."""

    document: Any
    warnings: tuple[str, ...] = field(default_factory=tuple)


def _loc(parts: tuple[int | str, ...]) -> str:
    out = ""
    for part in parts:
        if isinstance(part, int):
            out += f"[{part}]"
        elif part in ("base_velocity", "base_velocity_decay", "base_yaw_rate", "joint_velocity", "joint_position", "hold_position", "spring_return", "mode_set"):
            continue  # discriminator tag pydantic inserts into the location
        else:
            out += f".{part}" if out else str(part)
    return out or "(document)"


def pydantic_issues(error: ValidationError) -> list[str]:
    """One readable line per pydantic error: ``path: message``."""
    lines = []
    for item in error.errors():
        message = item["msg"].removeprefix("Value error, ")
        lines.append(f"{_loc(tuple(item['loc']))}: {message}")
    return lines


def parse_document(model: type[Model], raw: str | bytes | dict[str, Any], what: str) -> Model:
    """Parse JSON text or a dict into ``model``.

    Raises
    ------
    PlanValidationError
        Listing every schema violation with its field path.
    """
    try:
        if isinstance(raw, str | bytes):
            return model.model_validate_json(raw)
        return model.model_validate(raw)
    except ValidationError as exc:
        raise PlanValidationError(f"{what} is invalid", issues=pydantic_issues(exc)) from exc
    except ExpressionError as exc:
        raise PlanValidationError(f"{what} is invalid", issues=[exc.message]) from exc


def joint_limits(asset: ArticulatedAsset, joint: str) -> Limits:
    spec = asset.joints[joint]
    return Limits(lower=spec.lower, upper=spec.upper, rest=spec.rest)


def _joint_issue(asset: ArticulatedAsset, joint: str, where: str) -> str | None:
    if joint not in asset.joints:
        known = ", ".join(asset.controllable_joints) or "none"
        return f"{where}: unknown joint '{joint}' (movable joints: {known})"
    spec = asset.joints[joint]
    if not spec.movable:
        return f"{where}: joint '{joint}' is fixed and cannot move"
    if spec.mimic is not None:
        return f"{where}: joint '{joint}' mimics '{spec.mimic.joint}'; drive '{spec.mimic.joint}' instead"
    return None


def resolve_target(control: JointPosition, asset: ArticulatedAsset) -> float:
    """Numeric target of a position control: ``q_target_rad``, else the evaluated expression."""
    if control.q_target_rad is not None:
        return float(control.q_target_rad)
    assert control.q_target_expr is not None
    return evaluate_expr(control.q_target_expr, joint_limits(asset, control.joint))


def _position_issues(control: JointPosition, asset: ArticulatedAsset, where: str, warnings: list[str]) -> list[str]:
    spec = asset.joints[control.joint]
    issues: list[str] = []
    try:
        expr_value = None if control.q_target_expr is None else evaluate_expr(control.q_target_expr, joint_limits(asset, control.joint))
    except ExpressionError as exc:
        return [f"{where}.q_target_expr: {exc.message}"]
    target = control.q_target_rad if control.q_target_rad is not None else expr_value
    if expr_value is not None and control.q_target_rad is not None and abs(expr_value - control.q_target_rad) > TARGET_TOLERANCE:
        warnings.append(f"{where}: q_target_rad {control.q_target_rad:g} differs from q_target_expr '{control.q_target_expr}' = {expr_value:g}; using q_target_rad")
    if target is not None and spec.bounded and spec.lower is not None and spec.upper is not None:
        if not spec.lower - TARGET_TOLERANCE <= target <= spec.upper + TARGET_TOLERANCE:
            warnings.append(f"{where}: target {target:g} lies outside [{spec.lower:g}, {spec.upper:g}] of '{control.joint}' and will be clamped")
    return issues


def check_plan(plan: Plan, asset: ArticulatedAsset) -> tuple[str, ...]:
    """Check ``plan`` against ``asset``; returns warnings.

    Raises
    ------
    PlanValidationError
        Unknown or fixed joints, bad target expressions.
    """
    issues: list[str] = []
    warnings: list[str] = []
    for key in sorted(plan.model_extra or {}):
        warnings.append(f"unknown top-level key '{key}' ignored")
    for key in sorted(plan.physics.model_extra or {}):
        warnings.append(f"physics.{key}: unknown key kept but not used")
    if plan.timing_checks is not None:
        for key in sorted(plan.timing_checks.model_extra or {}):
            warnings.append(f"timing_checks.{key}: unknown key kept (informational)")
    for index, dynamics in enumerate(plan.physics.joint_dynamics):
        problem = _joint_issue(asset, dynamics.joint, f"physics.joint_dynamics[{index}].joint")
        if problem:
            issues.append(problem)
    if max(s.t1 for s in plan.timeline) > plan.meta.duration_s:
        warnings.append(f"timeline runs to {plan.duration_s:g} s, past meta.duration_s {plan.meta.duration_s:g} s; duration extended")
    for s_index, segment in enumerate(plan.timeline):
        for c_index, control in enumerate(segment.controls):
            where = f"timeline[{s_index}].controls[{c_index}]"
            if isinstance(control, JOINT_CONTROLS):
                problem = _joint_issue(asset, control.joint, f"{where}.joint")
                if problem:
                    issues.append(problem)
                    continue
                if isinstance(control, JointPosition):
                    issues.extend(_position_issues(control, asset, where, warnings))
    if issues:
        raise PlanValidationError("plan does not fit the asset", issues=issues)
    return tuple(warnings)


def validate_plan(raw: str | bytes | dict[str, Any] | Plan, asset: ArticulatedAsset) -> Checked:
    """Parse (if needed) and check a plan against ``asset``.

    Raises
    ------
    PlanValidationError
        Schema or asset problems, each naming its field.
    """
    plan = raw if isinstance(raw, Plan) else parse_document(Plan, raw, "plan")
    return Checked(document=plan, warnings=check_plan(plan, asset))


def check_causal(document: CausalDocument, asset: ArticulatedAsset) -> tuple[str, ...]:
    """Check link and joint names of a Causal.json against ``asset``; returns warnings.

    Raises
    ------
    PlanValidationError
        Unknown links or joints, or limit expressions a joint cannot evaluate.
    """
    issues: list[str] = []
    warnings: list[str] = []
    links = set(asset.links)

    def link(name: str, where: str) -> None:
        if name not in links:
            issues.append(f"{where}: unknown link '{name}' (links: {', '.join(asset.link_order)})")

    for index, item in enumerate(document.semantics.links):
        link(item.name, f"semantics.links[{index}].name")
    blocks = [("causal", document.causal.action, document.causal.effects)]
    blocks += [(f"causal_segments[{i}]", s.action, s.effects) for i, s in enumerate(document.causal_segments or [])]
    for prefix, action, effects in blocks:
        if action is not None:
            link(action.target_link, f"{prefix}.action.target_link")
            for index, name in enumerate(action.target_links):
                link(name, f"{prefix}.action.target_links[{index}]")
        if effects is None:
            continue
        for index, name in enumerate(effects.effect_links):
            link(name, f"{prefix}.effects.effect_links[{index}]")
        for index, target in enumerate(effects.joint_targets):
            where = f"{prefix}.effects.joint_targets[{index}]"
            problem = _joint_issue(asset, target.joint, f"{where}.joint")
            if problem:
                issues.append(problem)
            elif isinstance(target.to, str) and target.velocity is None:
                try:
                    evaluate_expr(target.to, joint_limits(asset, target.joint))
                except ExpressionError as exc:
                    issues.append(f"{where}.to: {exc.message}")
    if issues:
        raise PlanValidationError("causal document does not fit the asset", issues=issues)
    return tuple(warnings)


def validate_causal(raw: str | bytes | dict[str, Any] | CausalDocument, asset: ArticulatedAsset) -> Checked:
    """Parse (if needed) and check a Causal.json against ``asset``."""
    document = raw if isinstance(raw, CausalDocument) else parse_document(CausalDocument, raw, "causal document")
    return Checked(document=document, warnings=check_causal(document, asset))


def load_json_file(text: str, what: str) -> dict[str, Any]:
    """Parse JSON text into an object, with a readable error."""
    try:
        value = json.loads(text)
    except json.JSONDecodeError as exc:
        raise PlanValidationError(f"{what} is not valid JSON", issues=[f"line {exc.lineno} column {exc.colno}: {exc.msg}"]) from exc
    if not isinstance(value, dict):
        raise PlanValidationError(f"{what} must be a JSON object", issues=[f"(document): found {type(value).__name__}"])
    return value
