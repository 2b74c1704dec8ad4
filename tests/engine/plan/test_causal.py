"""Causal.json: the perceiver contract (paper supplementary §2.1) and its checks against an asset."""

from __future__ import annotations

import copy
from typing import Any

import pytest

from app.engine.asset.model import ArticulatedAsset
from app.engine.contracts.causal import CausalDocument
from app.engine.errors import PlanValidationError
from app.engine.plan.checks import validate_causal


def paper_causal() -> dict[str, Any]:
    """The paper's OUTPUT SCHEMA example, grounded on the cabinet."""
    return {
        "semantics": {
            "links": [
                {"name": "lid", "label": "lid", "affordance": ["lift"], "conf": 0.9, "description": "top lid"},
                {"name": "knob", "label": "knob", "affordance": ["turn"], "conf": 0.8, "description": "release knob"},
            ]
        },
        "causal": {
            "has_causal": True,
            "action": {
                "primitive": "turn",
                "target_link": "knob",
                "target_links": ["knob"],
                "target_role": "control",
                "magnitude": 0.0,
                "direction_axis_world": [1, 0, 0],
                "control_return_behavior": "self_return",
            },
            "effects": {
                "effect_links": ["lid"],
                "joint_targets": [
                    {"joint": "lid_hinge", "to": "upper_limit"},
                    {"joint": "knob_spin", "to": "velocity:3"},
                    {"joint": "drawer_slide", "to": 0.3},
                ],
                "modes": [{"name": "unlocked", "set": True}],
                "coupling_rules": ["knob turn releases the lid"],
            },
        },
        "causal_segments": None,
    }


def segment(action_link: str = "knob", effect_link: str = "lid") -> dict[str, Any]:
    return {
        "segment_id": "S1",
        "time_hint": {"order_index": 0, "overlap_ok": True},
        "action": {"primitive": "press", "target_link": action_link, "target_role": "control"},
        "effects": {"effect_links": [effect_link], "joint_targets": [{"joint": "lid_hinge", "to": "0.5*upper_limit"}]},
    }


def issues_of(raw: dict[str, Any], asset: ArticulatedAsset) -> list[str]:
    with pytest.raises(PlanValidationError) as caught:
        validate_causal(raw, asset)
    return caught.value.issues


def only_issue(raw: dict[str, Any], asset: ArticulatedAsset, path: str, says: str) -> None:
    issues = issues_of(raw, asset)
    assert len(issues) == 1 and issues[0].startswith(path + ": ") and says in issues[0], issues


def test_paper_example_validates(cabinet: ArticulatedAsset) -> None:
    document = validate_causal(paper_causal(), cabinet).document
    assert isinstance(document, CausalDocument)
    assert document.causal.action is not None and document.causal.action.direction_axis_world == (1.0, 0.0, 0.0)
    targets = document.all_joint_targets()
    assert [t.joint for t in targets] == ["lid_hinge", "knob_spin", "drawer_slide"]
    assert [t.velocity for t in targets] == [None, 3.0, None]
    assert CausalDocument.model_validate_json(document.dumps()) == document


def test_segment_form_validates(cabinet: ArticulatedAsset) -> None:
    raw = paper_causal()
    raw["causal_segments"] = [segment()]
    document = validate_causal(raw, cabinet).document
    assert [t.joint for t in document.all_joint_targets()] == ["lid_hinge", "knob_spin", "drawer_slide", "lid_hinge"]


def test_no_causal_effect(cabinet: ArticulatedAsset) -> None:
    raw = {
        "semantics": {"links": []},
        "causal": {"has_causal": False, "action": None, "effects": None},
        "causal_segments": None,
    }
    validate_causal(raw, cabinet)


@pytest.mark.parametrize("axis", [[0.5, 0, 0], [1, 1, 0], [0, 0, 2], [0.7071, 0.7071, 0]])
def test_direction_axis_must_be_a_signed_unit_axis(cabinet: ArticulatedAsset, axis: list[float]) -> None:
    raw = paper_causal()
    raw["causal"]["action"]["direction_axis_world"] = axis
    only_issue(raw, cabinet, "causal.action.direction_axis_world", "must be one of")


@pytest.mark.parametrize("axis", [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]])
def test_every_signed_unit_axis_is_accepted(cabinet: ArticulatedAsset, axis: list[float]) -> None:
    raw = paper_causal()
    raw["causal"]["action"]["direction_axis_world"] = axis
    validate_causal(raw, cabinet)


@pytest.mark.parametrize(
    ("to", "says"),
    [
        ("velocity:fast", "must be velocity:<number>"),
        ("velocity:unknown", "must be velocity:<number>"),
        ("__import__('os')", "unknown name '__import__'"),
        ("upper_limit +", "unexpected end"),
        ("alpha*upper_limit", "unknown name 'alpha'"),
    ],
)
def test_bad_joint_target(cabinet: ArticulatedAsset, to: str, says: str) -> None:
    raw = paper_causal()
    raw["causal"]["effects"]["joint_targets"][0]["to"] = to
    only_issue(raw, cabinet, "causal.effects.joint_targets[0].to", says)


def test_target_using_a_limit_the_joint_lacks(cabinet: ArticulatedAsset) -> None:
    raw = paper_causal()
    raw["causal"]["effects"]["joint_targets"][1]["to"] = "upper_limit"  # knob_spin is continuous
    only_issue(raw, cabinet, "causal.effects.joint_targets[1].to", "has no limits")


@pytest.mark.parametrize(
    ("where", "path"),
    [
        (lambda r: r["semantics"]["links"][1].update(name="ghost"), "semantics.links[1].name"),
        (
            lambda r: r["causal"]["action"].update(target_link="ghost", target_links=["ghost"]),
            "causal.action.target_link",
        ),
        (lambda r: r["causal"]["effects"].update(effect_links=["lid", "ghost"]), "causal.effects.effect_links[1]"),
    ],
)
def test_unknown_links(cabinet: ArticulatedAsset, where: Any, path: str) -> None:
    raw = paper_causal()
    where(raw)
    issues = issues_of(raw, cabinet)
    assert any(i.startswith(path + ": unknown link 'ghost'") for i in issues), issues


def test_unknown_links_in_segments(cabinet: ArticulatedAsset) -> None:
    raw = paper_causal()
    raw["causal_segments"] = [segment(action_link="ghost", effect_link="phantom")]
    issues = issues_of(raw, cabinet)
    assert issues[0].startswith("causal_segments[0].action.target_link: unknown link 'ghost'")
    assert issues[1].startswith("causal_segments[0].effects.effect_links[0]: unknown link 'phantom'")


@pytest.mark.parametrize(
    ("joint", "says"), [("ghost", "unknown joint"), ("root_fixed", "is fixed"), ("flap_mimic", "mimics")]
)
def test_joint_targets_must_be_drivable(cabinet: ArticulatedAsset, joint: str, says: str) -> None:
    raw = paper_causal()
    raw["causal"]["effects"]["joint_targets"][0]["joint"] = joint
    only_issue(raw, cabinet, "causal.effects.joint_targets[0].joint", says)


def test_structure_rules(cabinet: ArticulatedAsset) -> None:
    raw = paper_causal()
    raw["causal"]["has_causal"] = False
    only_issue(raw, cabinet, "causal", "has_causal=false requires action and effects to be null")
    raw = paper_causal()
    raw["causal"]["action"] = None
    only_issue(raw, cabinet, "causal", "has_causal=true requires an action")
    raw = paper_causal()
    raw["causal"]["action"]["target_links"] = ["lid"]
    only_issue(raw, cabinet, "causal.action", "target_link must appear in target_links")
    raw = paper_causal()
    raw["causal"]["action"]["target_role"] = "effect"
    only_issue(raw, cabinet, "causal.action.target_role", "'control' or 'direct_object'")
    raw = paper_causal()
    raw["causal"]["action"]["control_return_behavior"] = "self_return|stays|unknown"
    only_issue(raw, cabinet, "causal.action.control_return_behavior", "'self_return', 'stays' or 'unknown'")
    raw = paper_causal()
    raw["semantics"]["links"][0]["conf"] = 1.5
    only_issue(raw, cabinet, "semantics.links[0].conf", "less than or equal to 1")


def test_validation_does_not_mutate_input(cabinet: ArticulatedAsset) -> None:
    raw = paper_causal()
    before = copy.deepcopy(raw)
    validate_causal(raw, cabinet)
    assert raw == before
