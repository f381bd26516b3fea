"""LFSP: the language model as a few-shot planner (the paper's baseline).

The model is given the scene (workspace, every object's footprint, pose and
support) and the command, and answers with the pick-and-place actions
itself: ``{"actions": [{"object": id, "to": [x, y, theta], "on": id or null}]}``.
No goals are parsed and no search is run; the actions are executed in the
order given, and the plan is judged by the same validator and physics as
every other method (``lgmcts bench --method lfsp``). The answer is
constrained to that schema (``response_format``) and checked before it is
used (known ids, finite poses inside the workspace, no object placed on
itself); an unusable answer is sent back once with the error.

It runs over the same client as the LLM parser (:mod:`.llm`): any
OpenAI-compatible endpoint, configured the same way.
"""

from __future__ import annotations

import json
import math
import time
from typing import Any

from ..errors import InputError
from ..formats import Action, PlanSpec, SceneSpec
from .llm import LLMOptions, answer_items, ask_validated
from .matcher import pattern_infos

__all__ = ["plan_lfsp", "lfsp_messages", "lfsp_schema", "validate_actions", "scene_description"]


def _footprint(o) -> str:
    s = o.shape
    if s.type == "box":
        return f"box {s.size[0]:.3f} x {s.size[1]:.3f} m, {s.size[2]:.3f} m tall"
    if s.type == "cylinder":
        return f"round, radius {s.radius:.3f} m, {s.height:.3f} m tall"
    if s.type == "polygon":
        xs, ys = [p[0] for p in s.points], [p[1] for p in s.points]
        return f"flat shape about {max(xs) - min(xs):.3f} x {max(ys) - min(ys):.3f} m, {s.height:.3f} m tall"
    xs, ys = [p[0] for p in s.points], [p[1] for p in s.points]
    return f"seen as points spanning {max(xs) - min(xs):.3f} x {max(ys) - min(ys):.3f} m"


def _pose(o) -> tuple[float, float, float]:
    if o.pose is not None:
        return tuple(o.pose)
    xs, ys = [p[0] for p in o.shape.points], [p[1] for p in o.shape.points]
    return ((max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2, 0.0)


def scene_description(spec: SceneSpec) -> str:
    """The workspace and one line per object: id, colour and name, footprint, pose, support."""
    w = spec.workspace
    lines = [
        f"Workspace: x from {w.x[0]:.2f} to {w.x[1]:.2f} m, y from {w.y[0]:.2f} to {w.y[1]:.2f} m.",
        "Objects (id: colour name, shape, pose [x, y, theta]):",
    ]
    for o in spec.objects:
        x, y, th = _pose(o)
        on = f", resting on object {o.on}" if o.on is not None else ""
        color = f"{o.color} " if o.color else ""
        lines.append(f"- {o.id}: {color}{o.name}, {_footprint(o)}, at [{x:.3f}, {y:.3f}, {th:.2f}]{on}")
    return "\n".join(lines)


def _system_prompt() -> str:
    meanings = "\n".join(f"- {i.name}: {i.description}" for i in pattern_infos().values())
    return (
        "You are a robot arm that rearranges objects on a table by picking and placing them.\n"
        "The table frame: +x is to the viewer's right, +y is away from the viewer (behind), "
        "'front' is towards the viewer; poses are [x, y, theta] in metres and radians.\n"
        "Given the scene and a command, answer with the pick-and-place actions that make the command true, "
        "in the order they are to be executed: {\"actions\": [{\"object\": id, \"to\": [x, y, theta], "
        "\"on\": null or the id of the object to stack it on}], \"error\": null}.\n"
        "Rules: every placed object must lie inside the workspace and must not overlap any other object on the "
        "table; an object with something resting on it cannot be picked before that is moved; to stack, give "
        "'on' and the x, y of the object below; objects you do not move stay where they are.\n"
        "Words in commands mean:\n" + meanings + "\n"
        "If the command cannot be done in this scene, answer {\"actions\": [], \"error\": \"<one sentence>\"}."
    )


_EXAMPLE_SCENE = (
    "Workspace: x from -0.40 to 0.40 m, y from -0.30 to 0.30 m.\n"
    "Objects (id: colour name, shape, pose [x, y, theta]):\n"
    "- 1: red cup, round, radius 0.040 m, 0.100 m tall, at [-0.300, -0.200, 0.00]\n"
    "- 2: blue cup, round, radius 0.040 m, 0.100 m tall, at [0.250, 0.150, 0.00]\n"
    "- 3: green cup, round, radius 0.040 m, 0.100 m tall, at [0.050, -0.220, 0.00]\n"
    "- 4: white plate, round, radius 0.090 m, 0.020 m tall, at [-0.050, 0.000, 0.00]\n"
    "- 5: yellow box, box 0.050 x 0.050 m, 0.050 m tall, at [0.300, -0.150, 0.00]\n"
    "- 6: orange box, box 0.050 x 0.050 m, 0.050 m tall, at [-0.250, 0.200, 0.00]"
)
_EXAMPLES = (
    ("put all the cups in a line",
     {"actions": [{"object": 1, "to": [-0.15, 0.2, 0.0], "on": None},
                  {"object": 3, "to": [0.0, 0.2, 0.0], "on": None},
                  {"object": 2, "to": [0.15, 0.2, 0.0], "on": None}], "error": None}),
    ("place the yellow box to the left of the white plate",
     {"actions": [{"object": 5, "to": [-0.22, 0.0, 0.0], "on": None}], "error": None}),
    ("stack the orange box on the yellow box",
     {"actions": [{"object": 6, "to": [0.3, -0.15, 0.0], "on": 5}], "error": None}),
)


def lfsp_messages(spec: SceneSpec, text: str, *, few_shot: bool = True) -> list[dict]:
    """The conversation sent to the model."""
    msgs = [{"role": "system", "content": _system_prompt()}]
    if few_shot:
        for cmd, answer in _EXAMPLES:
            msgs.append({"role": "user", "content": _EXAMPLE_SCENE + "\n\nCommand: " + cmd})
            msgs.append({"role": "assistant", "content": json.dumps(answer)})
    msgs.append({"role": "user", "content": scene_description(spec) + "\n\nCommand: " + text})
    return msgs


def lfsp_schema(spec: SceneSpec) -> dict[str, Any]:
    """JSON schema of an answer for ``spec`` (ids limited to the scene's)."""
    oid = {"type": "integer", "enum": sorted(o.id for o in spec.objects)}
    return {
        "type": "object",
        "properties": {
            "actions": {
                "type": "array",
                "maxItems": 2 * len(spec.objects),
                "items": {
                    "type": "object",
                    "properties": {
                        "object": oid,
                        "to": {"type": "array", "items": {"type": "number"}, "minItems": 3, "maxItems": 3},
                        "on": {"anyOf": [oid, {"type": "null"}]},
                    },
                    "required": ["object", "to", "on"],
                    "additionalProperties": False,
                },
            },
            "error": {"anyOf": [{"type": "string"}, {"type": "null"}]},
        },
        "required": ["actions", "error"],
        "additionalProperties": False,
    }


def _number(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def validate_actions(content: str | None, spec: SceneSpec) -> list[Action]:
    """Actions of one answer, checked against the scene.

    Raises
    ------
    ValueError
        Malformed, or an unknown id, a pose outside the workspace, an object
        placed on itself (sent back to the model).
    InputError
        The model reports that the command cannot be done.
    """
    acts = answer_items(content, "actions", "plan")
    ids = {o.id for o in spec.objects}
    w = spec.workspace
    out = []
    for k, a in enumerate(acts):
        if not isinstance(a, dict):
            raise ValueError(f"action {k} is not an object")
        obj, to, on = a.get("object"), a.get("to"), a.get("on")
        if not isinstance(obj, int) or isinstance(obj, bool) or obj not in ids:
            raise ValueError(f"action {k}: unknown object id {obj!r}; the scene has ids {sorted(ids)}")
        if not isinstance(to, list) or len(to) != 3 or not all(_number(v) for v in to):
            raise ValueError(f"action {k}: 'to' must be [x, y, theta], three finite numbers")
        x, y, th = (float(v) for v in to)
        if not (w.x[0] <= x <= w.x[1] and w.y[0] <= y <= w.y[1]):
            raise ValueError(
                f"action {k}: [{x:.3f}, {y:.3f}] is outside the workspace "
                f"(x {w.x[0]:.2f}..{w.x[1]:.2f}, y {w.y[0]:.2f}..{w.y[1]:.2f})"
            )
        if on is not None and (not isinstance(on, int) or isinstance(on, bool) or on not in ids or on == obj):
            raise ValueError(f"action {k}: 'on' must be null or the id of another object")
        out.append(Action(object=obj, to=(x, y, th), on=on, purpose="goal"))
    return out


def plan_lfsp(spec: SceneSpec, text: str, *, options: LLMOptions | None = None) -> PlanSpec:
    """The model's own plan for ``text`` on ``spec``, unjudged.

    ``solved`` is true when the model gave a usable list of actions (whether
    they achieve anything is for :func:`lgmcts.validate.check` and the
    physics to say).

    Raises
    ------
    InputError
        No model configured, the endpoint failed, the model refused, or its
        answers stayed unusable.
    """
    if not isinstance(text, str) or not text.strip():
        raise InputError("the instruction is empty")
    options = options or LLMOptions()
    t0 = time.perf_counter()
    actions = ask_validated(
        options,
        lfsp_messages(spec, text, few_shot=options.few_shot),
        lfsp_schema(spec),
        lambda c: validate_actions(c, spec),
        name="pick_and_place_plan",
        what="actions",
    )
    dt = time.perf_counter() - t0
    return PlanSpec(solved=True, actions=actions, stats={"method": "lfsp", "iterations": 0, "time_s": round(dt, 6)})
