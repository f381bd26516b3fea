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
import math
import os
import re
import time
from dataclasses import dataclass
from typing import Any, Callable, TypeVar

from ..errors import InputError
from ..formats import GoalSpec, SceneSpec, parse_goals
from .matcher import PatternInfo, pattern_infos

__all__ = [
    "LLMOptions",
    "parse_llm",
    "system_prompt",
    "object_descriptions",
    "goal_schema",
    "validate_answer",
    "extract_json",
    "ask_validated",
    "few_shot_messages",
]

T = TypeVar("T")


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
    transport_retries : int
        How many times a request that failed in transit (connection refused
        or reset, timeout, HTTP 429 or 5xx) is sent again, after 0.5 s, 1 s, ...
    temperature : float
        Sampling temperature; 0 asks for the most likely answer.
    max_tokens : int
        Longest answer; bounds the time a small model can spend repeating itself.
    few_shot : bool
        Put worked examples (on a scene of their own) before the command;
        small models need them, large ones lose nothing by them.
    fold_system : bool, optional
        Send the system prompt as the start of the first user message, for
        chat formats without a system role (Gemma's: llama-cpp-python drops
        a system message there). Default: the ``LGMCTS_LLM_FOLD_SYSTEM``
        environment variable (``1`` to fold), else no.
    """

    model: str | None = None
    base_url: str | None = None
    api_key: str | None = None
    timeout: float = 30.0
    retries: int = 1
    transport_retries: int = 2
    temperature: float = 0.0
    max_tokens: int = 400
    few_shot: bool = True
    fold_system: bool | None = None


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
        "\"anchor\": id or null, \"pose\": [x, y, theta] or null}], \"error\": null}.\n"
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


def goal_schema(infos: dict[str, PatternInfo] | None = None, ids: list[int] | None = None) -> dict[str, Any]:
    """JSON schema of the answer (the goal format plus an optional error).

    With ``ids`` (the scene's object ids), object and anchor ids are limited
    to them, so that a server with constrained decoding cannot name an object
    the scene does not have.
    """
    infos = pattern_infos() if infos is None else infos
    oid: dict[str, Any] = {"type": "integer"}
    if ids:
        oid = {"type": "integer", "enum": sorted(ids)}
    objects: dict[str, Any] = {"type": "array", "items": oid, "minItems": 1}
    if ids:
        objects["maxItems"] = len(ids)
    # Every property is required and the optional ones are nullable: the form
    # that strict structured output (OpenAI's "strict": true) accepts.
    return {
        "type": "object",
        "properties": {
            "goals": {
                "type": "array",
                "maxItems": 8,
                "items": {
                    "type": "object",
                    "properties": {
                        "pattern": {"type": "string", "enum": sorted(infos)},
                        "objects": objects,
                        "anchor": {"anyOf": [oid, {"type": "null"}]},
                        "pose": {
                            "anyOf": [{"type": "array", "items": {"type": "number"}, "minItems": 3, "maxItems": 3}, {"type": "null"}]
                        },
                    },
                    "required": ["pattern", "objects", "anchor", "pose"],
                    "additionalProperties": False,
                },
            },
            "error": {"anyOf": [{"type": "string"}, {"type": "null"}]},
        },
        "required": ["goals", "error"],
        "additionalProperties": False,
    }


_FENCE = re.compile(r"```(?:json)?\s*(.*?)\s*```", re.S)


def extract_json(content: str | None) -> Any:
    """The JSON value of an answer: bare, in a code fence, or the first
    ``{...}`` in surrounding prose.

    Raises
    ------
    ValueError
        No JSON object can be read (the message says why, for the model).
    """
    text = (content or "").strip()
    if not text:
        raise ValueError("the answer is empty")
    m = _FENCE.search(text)
    if m:
        text = m.group(1)
    try:
        return json.loads(text)
    except json.JSONDecodeError as exc:
        first = exc
    start = text.find("{")
    if start >= 0:
        try:
            value, _ = json.JSONDecoder().raw_decode(text[start:])
            return value
        except json.JSONDecodeError:
            pass
    raise ValueError(f"the answer is not valid JSON ({first.msg} at position {first.pos})")


def answer_items(content: str | None, key: str, doing: str) -> list:
    """The non-empty list under ``key`` of an answer that is a JSON object.

    Raises ``ValueError`` (sent back to the model) when the answer has no such
    list, and :class:`InputError` when the model reports instead, under
    ``"error"``, that it cannot ``doing`` the command.
    """
    data = extract_json(content)
    if not isinstance(data, dict):
        article = "an" if key[0] in "aeiou" else "a"
        raise ValueError(f"the answer must be a JSON object with {article} '{key}' list")
    items = data.get(key)
    if data.get("error") and not items:
        reason = " ".join(str(data["error"]).split())[:200]
        raise InputError(f"the language model could not {doing} the command: {reason}")
    if not isinstance(items, list) or not items:
        raise ValueError(f"the answer must have a non-empty '{key}' list")
    return items


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
    goals = answer_items(content, "goals", "parse")
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
        if len(set(objs)) != len(objs):
            raise ValueError(f"goal {k}: an object id is listed twice")
        if len(objs) < info.min_objects:
            raise ValueError(f"goal {k}: a {p} needs at least {info.min_objects} objects, got {len(objs)}")
        item: dict[str, Any] = {"pattern": p, "objects": objs}
        anchor = g.get("anchor")
        if info.anchored:
            if not isinstance(anchor, int) or isinstance(anchor, bool) or anchor not in ids:
                raise ValueError(f"goal {k}: a {p} goal needs 'anchor', the id of an object in the scene")
            if anchor in objs:
                raise ValueError(f"goal {k}: the anchor {anchor} cannot also be one of the objects placed")
            item["anchor"] = anchor
        if info.needs_pose:
            pose = g.get("pose")
            if (
                not isinstance(pose, list)
                or len(pose) != 3
                or not all(isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) for v in pose)
            ):
                raise ValueError(f"goal {k}: a {p} goal needs 'pose': [x, y, theta], three finite numbers")
            item["pose"] = pose
        clean.append(item)
    try:
        out = parse_goals({"goals": clean})
        out.check_against(spec)
    except InputError as exc:
        raise ValueError(str(exc)) from None
    return out


# ------------------------------------------------------------------ transport


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


def _formats(schema: dict, name: str) -> list[dict | None]:
    """Ways to ask for schema-constrained output, most standard first.

    ``json_schema`` is the OpenAI form (also vLLM, Ollama, llama.cpp's own
    server); ``json_object`` with a ``schema`` is the form of
    llama-cpp-python's server (and Anyscale-style endpoints); ``None`` asks
    without constraint (the answer is validated all the same).
    """
    return [
        {"type": "json_schema", "json_schema": {"name": name, "schema": schema, "strict": True}},
        {"type": "json_object", "schema": schema},
        None,
    ]


#: The first form of :func:`_formats` each endpoint (base URL, model) accepted;
#: forms it answered with HTTP 400/422 are not tried again in this process.
_FORMAT: dict[tuple[str, str], int] = {}


def _ask(client: Any, options: LLMOptions, model: str, messages: list[dict], schema: dict, name: str) -> str | None:
    """One answer; transient failures are retried, the rest become one-line errors."""
    import openai

    where = (str(client.base_url), model)
    forms = _formats(schema, name)
    tries = 0
    while True:
        k = _FORMAT.get(where, 0)
        kwargs: dict[str, Any] = {"model": model, "messages": messages, "temperature": options.temperature,
                                  "max_tokens": options.max_tokens}
        if forms[k] is not None:
            kwargs["response_format"] = forms[k]
        try:
            resp = client.chat.completions.create(**kwargs)
            break
        except openai.APIStatusError as exc:
            # A form of structured output the server does not take: HTTP 400/422,
            # or (llama-cpp-python) HTTP 500 whose message names response_format.
            unsupported = exc.status_code in (400, 422) or (
                exc.status_code == 500 and forms[k] is not None and "response_format" in str(exc)
            )
            if not unsupported:
                err = exc
            elif k + 1 >= len(forms):
                raise InputError(f"the language model endpoint rejected the request (HTTP {exc.status_code})") from None
            else:
                _FORMAT[where] = k + 1
                continue
            if isinstance(err, (openai.AuthenticationError, openai.PermissionDeniedError)):
                raise InputError("the language model endpoint rejected the API key") from None
            if isinstance(err, openai.NotFoundError):
                raise InputError(f"the language model endpoint has no model '{model}' (HTTP 404)") from None
            if (err.status_code == 429 or err.status_code >= 500) and tries < options.transport_retries:
                time.sleep(0.5 * 2**tries)
                tries += 1
                continue
            raise InputError(f"the language model endpoint answered HTTP {err.status_code}") from None
        except (openai.APITimeoutError, openai.APIConnectionError) as exc:
            if tries < options.transport_retries:
                time.sleep(0.5 * 2**tries)
                tries += 1
                continue
            if isinstance(exc, openai.APITimeoutError):
                raise InputError(f"the language model did not answer within {options.timeout:g} s") from None
            raise InputError(f"cannot reach the language model at {client.base_url}") from None
    try:
        return resp.choices[0].message.content
    except (AttributeError, IndexError, TypeError):
        return None


def ask_validated(
    options: LLMOptions,
    messages: list[dict],
    schema: dict,
    validate: Callable[[str | None], T],
    *,
    name: str,
    what: str,
) -> T:
    """Ask, validate, send an invalid answer back with its error up to
    ``options.retries`` times, else raise one :class:`InputError`.

    ``validate`` raises :class:`ValueError` for an answer worth correcting and
    :class:`InputError` for a final refusal.
    """
    model = options.model or os.environ.get("LGMCTS_LLM_MODEL")
    if not model:
        raise InputError("the LLM needs a model name: --llm-model NAME (or LGMCTS_LLM_MODEL)")
    client = _client(options)
    fold = options.fold_system
    if fold is None:
        fold = os.environ.get("LGMCTS_LLM_FOLD_SYSTEM", "") not in ("", "0")
    if fold and len(messages) > 1 and messages[0]["role"] == "system" and messages[1]["role"] == "user":
        first = {"role": "user", "content": messages[0]["content"] + "\n\n" + messages[1]["content"]}
        messages = [first, *messages[2:]]
    error = ""
    for _ in range(options.retries + 1):
        content = _ask(client, options, model, messages, schema, name)
        try:
            return validate(content)
        except InputError:
            raise
        except ValueError as exc:
            error = " ".join(str(exc).split())
        messages = messages + [
            {"role": "assistant", "content": (content or "")[:2000]},
            {"role": "user", "content": f"That answer is invalid: {error}. Answer again with corrected JSON only."},
        ]
    raise InputError(f"the language model gave no valid {what} after {options.retries + 1} tries: {error}")


# ------------------------------------------------------------------ the parser

#: A scene of its own for the worked examples (none of the evaluation scenes).
_EXAMPLE_SCENE = (
    "Objects in the scene:\n"
    "- id 1: red cup\n- id 2: blue cup\n- id 3: green cup\n- id 4: white plate\n"
    "- id 5: yellow box\n- id 6: orange box\n- id 7: black pen"
)
_EXAMPLES = (
    ("arrange all the cups in a line",
     {"goals": [{"pattern": "line", "objects": [1, 2, 3], "anchor": None, "pose": None}], "error": None}),
    ("put the black pen to the left of the white plate",
     {"goals": [{"pattern": "left", "objects": [7], "anchor": 4, "pose": None}], "error": None}),
    ("stack the orange box on the yellow box and place the blue cup in front of the plate",
     {"goals": [{"pattern": "tower", "objects": [5, 6], "anchor": None, "pose": None},
                {"pattern": "front", "objects": [2], "anchor": 4, "pose": None}], "error": None}),
    ("put the pink elephant behind the plate",
     {"goals": [], "error": "the scene has no pink elephant"}),
)


def few_shot_messages() -> list[dict]:
    """The worked examples as user/assistant turns."""
    out = []
    for text, answer in _EXAMPLES:
        out.append({"role": "user", "content": _EXAMPLE_SCENE + "\n\nCommand: " + text})
        out.append({"role": "assistant", "content": json.dumps(answer)})
    return out


def parse_llm(spec: SceneSpec, text: str, *, options: LLMOptions | None = None) -> GoalSpec:
    """Ask the model for goals, validate them, retry once with the error.

    Raises
    ------
    InputError
        No model configured, the endpoint failed, the model reported the
        command as not understood, or its answers stayed invalid.
    """
    options = options or LLMOptions()
    infos = pattern_infos()
    messages = [{"role": "system", "content": system_prompt(infos)}]
    if options.few_shot:
        messages += few_shot_messages()
    messages.append({"role": "user", "content": object_descriptions(spec) + "\n\nCommand: " + text})
    schema = goal_schema(infos, [o.id for o in spec.objects])
    return ask_validated(
        options, messages, schema, lambda c: validate_answer(c, spec, infos), name="goal_spec", what="goals"
    )
