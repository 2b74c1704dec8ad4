"""Golden-hash determinism: a plan using all seven modes on a real asset gives pinned bytes."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from app.engine.asset.loader import load_asset
from app.engine.execute.executor import execute
from app.engine.export.jsonl import dumps_trajectory, write_trajectory_jsonl
from app.engine.plan.checks import validate_plan

ASSET = "safe_101593"  # joint_0 revolute door [0, 2.967], joint_1 / joint_2 continuous dials
GOLDEN_SHA256 = "8639742490f541f79deb8f49659b52de45c68799bd41a6409c4eb35048d9c3c3"
"""sha256 of the trajectory.jsonl records with numbers rounded to 10 decimals (``_canonical``); change only with a
deliberate change of executor semantics. Same-machine runs are compared byte for byte above."""


def all_modes_plan() -> dict[str, Any]:
    return {
        "meta": {"fps": 30, "duration_s": 3.5},
        "physics": {"joint_dynamics": [{"joint": "joint_0", "damping_c": 1.5}], "friction": 0.2},
        "timeline": [
            {
                "name": "turn the dials",
                "phase_type": "control_actuation",
                "t0": 0.0,
                "t1": 0.8,
                "controls": [
                    {"mode": "joint_velocity", "joint": "joint_1", "omega_radps": 3.0, "ramp_to_omega_radps": 6.0},
                    {
                        "mode": "joint_velocity",
                        "joint": "joint_2",
                        "omega_radps": -4.0,
                        "decay": {"type": "exponential", "tau_s": 0.4, "min_omega_radps": 0.5},
                    },
                    {"mode": "mode_set", "name": "unlocked", "set": True},
                ],
            },
            {
                "name": "latency",
                "phase_type": "causal_latency",
                "t0": 0.8,
                "t1": 1.0,
                "controls": [{"mode": "hold_position", "joint": "joint_1"}],
            },
            {
                "name": "swing the door",
                "phase_type": "effect_motion",
                "t0": 1.0,
                "t1": 2.5,
                "controls": [
                    {
                        "mode": "joint_position",
                        "joint": "joint_0",
                        "q_target_expr": "0.8*upper_limit",
                        "curve": "ease_in_out",
                    },
                    {"mode": "base_velocity", "axis_world": [0, 2, 0], "v_mps": 0.1},
                ],
            },
            {
                "name": "settle",
                "phase_type": "settle",
                "t0": 2.5,
                "t1": 3.5,
                "controls": [
                    {"mode": "spring_return", "joint": "joint_0", "spring_k": 8.0, "rest_position": 1.2},
                    {"mode": "base_velocity_decay", "axis_world": [1, 0, 0], "v0_mps": 0.3, "tau_s": 0.4},
                ],
            },
        ],
        "timing_checks": {"control_onset_time": 0.0, "effect_start_time": 1.0, "enforced_delay_s": 0.2},
    }


def test_all_modes_are_deterministic_and_pinned(partnet: Path, tmp_path: Path) -> None:
    asset = load_asset(partnet / ASSET)
    plan = validate_plan(all_modes_plan(), asset).document
    first, second = execute(plan, asset), execute(plan, asset)
    for name in ("times", "q", "base_translation", "base_rotation_xyzw"):
        assert getattr(first, name).tobytes() == getattr(second, name).tobytes(), name
    assert first.modes == second.modes and first.events == second.events
    assert first.frame_count == 106 and first.joint_names == ("joint_0", "joint_1", "joint_2")
    text = dumps_trajectory(first)
    assert text == dumps_trajectory(second)
    written = write_trajectory_jsonl(first, tmp_path / "trajectory.jsonl")
    assert written.read_text(encoding="utf-8") == text
    # sanity of what is pinned: each mode left its mark
    assert first.joint("joint_1")[24] == pytest.approx(3.0 * 0.8 + 3.0 * 0.8 / 2, abs=1e-6)  # ramp 3 -> 6 over 0.8 s
    assert first.joint("joint_2")[-1] < 0 and first.modes[-1] == {"unlocked": True}
    assert first.joint("joint_0")[75] == pytest.approx(0.8 * asset.joints["joint_0"].upper, abs=1e-12)  # type: ignore[operator]
    assert np.allclose(first.base_translation[-1], [0.3 * 0.4 * (1 - np.exp(-2.5)), 0.15, 0.0])
    assert hashlib.sha256(_canonical(text).encode("utf-8")).hexdigest() == GOLDEN_SHA256


def _canonical(text: str) -> str:
    """The trajectory with every number rounded to 10 decimals: the same on every CPU (numpy's vectorised exp / sin may
    differ in the last bit between instruction sets), still every value the executor computes."""
    def rounded(value: Any) -> Any:
        if isinstance(value, float):
            return round(value, 10) + 0.0
        if isinstance(value, list):
            return [rounded(v) for v in value]
        if isinstance(value, dict):
            return {k: rounded(v) for k, v in value.items()}
        return value

    return "\n".join(json.dumps(rounded(json.loads(line)), sort_keys=True) for line in text.splitlines())
