"""Optional LLM parser over any OpenAI-compatible Chat Completions endpoint.

The prompt follows the paper ("Language Parsing & Object Selection"): a
system prompt with the rules and the pattern database (names and meanings
from :func:`lgmcts.patterns.registry`, the same database the offline parser
matches against), the object descriptions (ids, names, colours) and the
user's command. The answer is constrained to the goal JSON schema
(``response_format`` of type ``json_schema``; servers that reject it are asked
again without it) and validated against the scene anyway: unknown ids,
unknown patterns, missing anchors, too few objects. An invalid answer is sent
back once with the validation error; a second invalid answer is a clear
:class:`~lgmcts.errors.InputError`.

Works with OpenAI, vLLM, llama.cpp server, Ollama and anything else that
speaks ``POST {base_url}/chat/completions``.
"""

from __future__ import annotations

import json
import os
import re
from dataclasses import dataclass
from typing import Any

from ..errors import InputError
from ..formats import GoalSpec, SceneSpec, parse_goals
from .matcher import PatternInfo, pattern_infos

__all__ = ["LLMOptions", "parse_llm", "system_prompt", "object_descriptions", "goal_schema", "validate_answer"]


@dataclass(frozen=True)
class LLMOptions:
    """Where and how to ask the language model.

    Attributes
    ----------
    model : str, optional
        Model name (default: the ``LGMCTS_LLM_MODEL`` environment variable).
    base_url : str, optional
        OpenAI-compatible base URL, e.g. ``http://127.0.0.1:8000/v1``
        (default: ``OPENAI_BASE_URL`` or OpenAI itself).
    api_key : str, optional
        Key (default: ``OPENAI_API_KEY``; local servers need none).
    timeout : float
        Seconds to wait for one answer.
    retries : int
        How many times an invalid answer is sent back with its error.
    temperature : float
        Sampling temperature; 0 asks for the most likely answer.
    """

    model: str | None = None
    base_url: str | None = None
    api_key: str | None = None
    timeout: float = 30.0
    retries: int = 1
    temperature: float = 0.0


def system_prompt(infos: dict[str, PatternInfo] | None = None) -> str:
    """Instructions and the pattern database, in the words of the registry."""
    infos = pattern_infos() if infos is None else infos
    lines = []
    for info in infos.values():
        extra = []
        if info.anchored:
            extra.append("needs 'anchor': the id of the reference object")
        if info.needs_pose:
            extra.append("needs 'pose': [x, y, theta] in metres and radians")
        if info.name == "tower" or (info.ordered and not info.anchored):
            extra.append("'objects' in order, first one at the bottom")
        extra.append(f"at least {info.min_objects} object{'s' if info.min_objects > 1 else ''}")
        lines.append(f"- {info.name}: {info.description} ({'; '.join(extra)})")
    return (
        "You turn a person's tabletop rearrangement command into goals for a robot planner.\n"
        "The table frame: +x is to the viewer's right, +y is away from the viewer (behind), "
        "'front' is towards the viewer.\n"
        "Patterns you may use (and no others):\n" + "\n".join(lines) + "\n"
        "Rules:\n"
        "- Answer with one JSON object only: {\"goals\": [{\"pattern\": ..., \"objects\": [ids], "
        "\"anchor\": id or null}]}.\n"
        "- Use only the object ids listed in the scene. Split a composite command into one goal per pattern.\n"
        "- 'all X' means every matching object; 'one X' means any one of them; for a relation to 'one X' "
        "prefer an X that another goal of the same command uses.\n"
        "- If the command names an object the scene does not have, a pattern not listed, is ambiguous or "
        "contradicts itself, answer {\"goals\": [], \"error\": \"<one sentence saying what is wrong>\"}."
    )


def object_descriptions(spec: SceneSpec) -> str:
    """One line per object: id, colour, name, and what it rests on."""
    out = []
    for o in spec.objects:
        on = f", on object {o.on}" if o.on is not None else ""
        color = f"{o.color} " if o.color else ""
        out.append(f"- id {o.id}: {color}{o.name}{on}")
    return "Objects in the scene:\n" + "\n".join(out)


def goal_schema(infos: dict[str, PatternInfo] | None = None) -> dict[str, Any]:
    """JSON schema of the answer (the goal format plus an optional error)."""
    infos = pattern_infos() if infos is None else infos
    return {
        "type": "object",
        "properties": {
            "goals": {
                "type": "array",
                "items": {
                    "type": "object",
                    "properties": {
                        "pattern": {"type": "string", "enum": sorted(infos)},
                        "objects": {"type": "array", "items": {"type": "integer"}},
                        "anchor": {"type": ["integer", "null"]},
                        "pose": {"type": ["array", "null"], "items": {"type": "number"}},
                    },
                    "required": ["pattern", "objects"],
                    "additionalProperties": False,
                },
            },
            "error": {"type": "string"},
        },
        "required": ["goals"],
        "additionalProperties": False,
    }


_FENCE = re.compile(r"^```(?:json)?\s*(.*?)\s*```$", re.S)


def validate_answer(content: str | None, spec: SceneSpec, infos: dict[str, PatternInfo] | None = None) -> GoalSpec:
    """Check one answer against the schema and the scene.

    Raises
    ------
    ValueError
        The answer is malformed or refers to things the scene or database
        does not have (the message is sent back to the model).
    InputError
        The model itself reports that the command cannot be parsed.
    """
    infos = pattern_infos() if infos is None else infos
    text = (content or "").strip()
    m = _FENCE.match(text)
    if m:
        text = m.group(1)
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise ValueError(f"the answer is not valid JSON ({exc.msg} at position {exc.pos})") from None
    if not isinstance(data, dict):
        raise ValueError("the answer must be a JSON object with a 'goals' list")
    goals = data.get("goals")
    if data.get("error") and not goals:
        raise InputError(f"the language model could not parse the command: {data['error']}")
    if not isinstance(goals, list) or not goals:
        raise ValueError("the answer must have a non-empty 'goals' list")
    ids = {o.id for o in spec.objects}
    clean = []
    for k, g in enumerate(goals):
        if not isinstance(g, dict):
            raise ValueError(f"goal {k} is not an object")
        p = g.get("pattern")
        if p not in infos:
            raise ValueError(f"goal {k}: unknown pattern {p!r}; use one of {', '.join(sorted(infos))}")
        info = infos[p]
        objs = g.get("objects")
        if not isinstance(objs, list) or not all(isinstance(i, int) and not isinstance(i, bool) for i in objs):
            raise ValueError(f"goal {k}: 'objects' must be a list of integer ids")
        bad = [i for i in objs if i not in ids]
        if bad:
            raise ValueError(f"goal {k}: unknown object id {bad[0]}; the scene has ids {sorted(ids)}")
        if len(objs) < info.min_objects:
            raise ValueError(f"goal {k}: a {p} needs at least {info.min_objects} objects, got {len(objs)}")
        item: dict[str, Any] = {"pattern": p, "objects": objs}
        anchor = g.get("anchor")
        if info.anchored:
            if not isinstance(anchor, int) or anchor not in ids:
                raise ValueError(f"goal {k}: a {p} goal needs 'anchor', the id of an object in the scene")
            item["anchor"] = anchor
        if info.needs_pose:
            item["pose"] = g.get("pose")
        clean.append(item)
    try:
        out = parse_goals({"goals": clean})
        out.check_against(spec)
    except InputError as exc:
        raise ValueError(str(exc)) from None
    return out


def _client(options: LLMOptions) -> Any:
    try:
        import openai
    except ModuleNotFoundError:
        raise InputError("the LLM parser needs the 'llm' extra (openai is not installed): pip install 'lgmcts[llm]'") from None
    base_url = options.base_url or os.environ.get("OPENAI_BASE_URL")
    key = options.api_key or os.environ.get("OPENAI_API_KEY")
    if not key:
        if base_url is None:
            raise InputError("--parser llm needs OPENAI_API_KEY (or --llm-base-url for a local server)")
        key = "none"
    return openai.OpenAI(api_key=key, base_url=base_url, timeout=options.timeout, max_retries=0)


def _ask(client: Any, options: LLMOptions, model: str, messages: list[dict], schema: dict) -> str | None:
    import openai

    fmt = {"type": "json_schema", "json_schema": {"name": "goal_spec", "schema": schema}}
    try:
        try:
            resp = client.chat.completions.create(
                model=model, messages=messages, temperature=options.temperature, response_format=fmt
            )
        except openai.BadRequestError:
            # Some servers do not support structured output; the answer is validated anyway.
            resp = client.chat.completions.create(model=model, messages=messages, temperature=options.temperature)
    except openai.APITimeoutError:
        raise InputError(f"the language model did not answer within {options.timeout:g} s") from None
    except openai.APIConnectionError:
        raise InputError(f"cannot reach the language model at {client.base_url}") from None
    except openai.AuthenticationError:
        raise InputError("the language model endpoint rejected the API key") from None
    except openai.APIStatusError as exc:
        raise InputError(f"the language model endpoint answered HTTP {exc.status_code}") from None
    try:
        return resp.choices[0].message.content
    except (AttributeError, IndexError, TypeError):
        return None


def parse_llm(spec: SceneSpec, text: str, *, options: LLMOptions | None = None) -> GoalSpec:
    """Ask the model for goals, validate them, retry once with the error.

    Raises
    ------
    InputError
        No model configured, the endpoint failed, the model reported the
        command as not understood, or its answers stayed invalid.
    """
    options = options or LLMOptions()
    model = options.model or os.environ.get("LGMCTS_LLM_MODEL")
    if not model:
        raise InputError("--parser llm needs --llm-model NAME (or LGMCTS_LLM_MODEL)")
    infos = pattern_infos()
    client = _client(options)
    messages = [
        {"role": "system", "content": system_prompt(infos)},
        {"role": "user", "content": object_descriptions(spec) + "\n\nCommand: " + text},
    ]
    schema = goal_schema(infos)
    error = ""
    for attempt in range(options.retries + 1):
        content = _ask(client, options, model, messages, schema)
        try:
            return validate_answer(content, spec, infos)
        except InputError:
            raise
        except ValueError as exc:
            error = str(exc)
        messages = messages + [
            {"role": "assistant", "content": content or ""},
            {"role": "user", "content": f"That answer is invalid: {error}. Answer again with corrected JSON only."},
        ]
    raise InputError(f"the language model gave no valid goals after {options.retries + 1} tries: {error}")
