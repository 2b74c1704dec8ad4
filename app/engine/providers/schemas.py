"""Reply schemas for structured output, from the roles' pydantic models.

OpenAI's ``response_format: json_schema`` takes the JSON Schema as pydantic writes it
(non-strict mode: ``$defs``/``$ref`` allowed). Gemini's ``responseSchema`` takes an
OpenAPI subset: no ``$ref``, no ``additionalProperties``, ``nullable`` instead of a null
type, ``enum`` (strings only) instead of ``const``, fixed-length arrays without
``prefixItems``;
:func:`gemini_schema` rewrites a JSON Schema into it.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

from pydantic import BaseModel

GEMINI_KEYS = {"type", "format", "description", "nullable", "enum", "properties", "required", "items", "minItems", "maxItems",
               "minimum", "maximum", "anyOf", "propertyOrdering", "minLength", "maxLength"}
MAX_DEPTH = 24


@lru_cache(maxsize=32)
def _cached(model: type[BaseModel]) -> dict[str, Any]:
    return model.model_json_schema()


def json_schema(model: type[BaseModel]) -> dict[str, Any]:
    """The JSON Schema of ``model``'s JSON form (a fresh copy)."""
    return _copy(_cached(model))


def _copy(value: Any) -> Any:
    if isinstance(value, dict):
        return {k: _copy(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_copy(v) for v in value]
    return value


def _resolve(node: dict[str, Any], defs: dict[str, Any]) -> dict[str, Any]:
    ref = node.get("$ref")
    if isinstance(ref, str) and ref.startswith("#/$defs/"):
        merged = {**defs[ref.removeprefix("#/$defs/")], **{k: v for k, v in node.items() if k != "$ref"}}
        return _resolve(merged, defs)
    return node


def _convert(node: Any, defs: dict[str, Any], depth: int) -> dict[str, Any]:
    if not isinstance(node, dict) or depth > MAX_DEPTH:
        return {"type": "string"}
    node = _resolve(node, defs)
    variants = node.get("anyOf") or node.get("oneOf")
    if variants:
        kept = [v for v in variants if not (isinstance(v, dict) and v.get("type") == "null")]
        nullable = len(kept) < len(variants)
        merged: dict[str, Any] = _convert(kept[0], defs, depth + 1) if len(kept) == 1 else {"anyOf": [_convert(v, defs, depth + 1) for v in kept]}
        if nullable:
            merged["nullable"] = True
        if "description" in node:
            merged.setdefault("description", node["description"])
        return merged
    out: dict[str, Any] = {}
    kind = node.get("type")
    if isinstance(kind, list):
        named = [k for k in kind if k != "null"]
        kind = named[0] if named else "string"
        if len(named) < len(node["type"]):
            out["nullable"] = True
    if "const" in node:
        out["enum"] = [node["const"]]
        kind = kind or "string"
    if kind:
        out["type"] = kind
    for key, value in node.items():
        if key in ("properties", "items", "anyOf", "type", "prefixItems") or key not in GEMINI_KEYS:
            continue
        out[key] = value
    if "enum" in out and not all(isinstance(v, str) for v in out["enum"]):
        out.pop("enum")  # Gemini enums are strings only; the type still constrains the value
    if kind == "object":
        properties = {name: _convert(value, defs, depth + 1) for name, value in (node.get("properties") or {}).items()
                      if not (isinstance(value, dict) and value.get("type") == "null")}
        if properties:
            out["properties"] = properties
            out["propertyOrdering"] = list(properties)
        out["required"] = [r for r in node.get("required", []) if r in properties]
        if not out["required"]:
            out.pop("required")
    if kind == "array":
        items = node.get("items") or (node.get("prefixItems") or [{"type": "string"}])[0]
        out["items"] = _convert(items, defs, depth + 1)
        if "prefixItems" in node:
            out["minItems"] = out["maxItems"] = len(node["prefixItems"])
    return out


@lru_cache(maxsize=32)
def _gemini_cached(model: type[BaseModel]) -> dict[str, Any]:
    schema = _cached(model)
    return _convert(schema, schema.get("$defs", {}), 0)


def gemini_schema(model: type[BaseModel]) -> dict[str, Any]:
    """``model``'s schema in Gemini's ``responseSchema`` dialect (a fresh copy)."""
    return _copy(_gemini_cached(model))
