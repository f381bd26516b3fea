"""The rewrite engine: an ordered table of text rewrites, read from ``data/rewrites.toml``.

Each ``[[rewrite]]`` row of the table has

* ``id``: a unique name (used in test reports and in ``trace``);
* ``pattern``: a regular expression, in which ``{NAME}`` (capitals) is a macro
  expanded from the lexicon (:data:`lexicon.MACROS`: ``{HUE}``, ``{SHAPE}`` ...)
  or from the table's own ``[macros]``; and one of

  * ``replace``: a :func:`re.sub` template (``\\1`` for a group),
  * ``fn``: the name of a replacement function ``(re.Match) -> str``
    registered with :func:`replacer`,
  * ``step``: the name of a function ``(str) -> str`` registered with
    :func:`step` that rewrites the whole text (a step has no ``pattern``);

* optionally ``count`` (at most that many replacements), ``when`` / ``unless``
  (an expression or a list: the row applies only when every ``when`` and no
  ``unless`` expression is found in the text),
  ``note`` (why the row exists) and ``examples``: ``[input, output]`` pairs
  that the row alone turns one into the other (``tests/language/test_rewrites.py``
  runs them all).

Rows apply in the order of the file, each to the output of the one before.
The file holds more than one table: ``[[rewrite]]`` rows make :func:`apply`'s
default chain, ``[[frame]]`` rows strip the words that frame a request as an
end state or open it in speech (:func:`.rewrite.unframe`), ``[[plain]]`` rows
say a trade's own words for the table's sides plainly before anything else
reads the command ("frame left", "the foreground"); ``apply(text, "frame")``
runs one table by name. Nothing here knows the scene.
"""

from __future__ import annotations

import re
import tomllib
from collections.abc import Callable
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

# A pattern's parse tree and its opcodes, for the literal words of Rule.could_match (no public name).
import re._constants as _sre  # type: ignore[import-not-found]
import re._parser as _sre_parse  # type: ignore[import-not-found]

__all__ = ["TABLE", "TABLES", "Rule", "apply", "expand", "literal_needs", "replacer", "rules", "step", "trace"]

#: The table of rewrites, in order.
TABLE = Path(__file__).with_name("data") / "rewrites.toml"

_STEPS: dict[str, Callable[[str], str]] = {}
_REPLACERS: dict[str, Callable[[re.Match[str]], str]] = {}
_MACRO = re.compile(r"\{([A-Z][A-Z_]*)\}")


def step(name: str) -> Callable[[Callable[[str], str]], Callable[[str], str]]:
    """Register ``fn`` as the whole-text step ``name`` of the table."""
    def add(fn: Callable[[str], str]) -> Callable[[str], str]:
        if name in _STEPS:
            raise ValueError(f"rewrite step {name!r} registered twice")
        _STEPS[name] = fn
        return fn
    return add


def replacer(name: str) -> Callable[[Callable[[re.Match[str]], str]], Callable[[re.Match[str]], str]]:
    """Register ``fn`` as the replacement function ``name`` of the table."""
    def add(fn: Callable[[re.Match[str]], str]) -> Callable[[re.Match[str]], str]:
        if name in _REPLACERS:
            raise ValueError(f"rewrite replacer {name!r} registered twice")
        _REPLACERS[name] = fn
        return fn
    return add


def expand(pattern: str, macros: dict[str, str] | None = None) -> str:
    """``pattern`` with every ``{NAME}`` macro replaced (table macros first, then the lexicon's)."""
    from .lexicon import MACROS

    table = _table_macros() if macros is None else macros

    def one(m: re.Match[str]) -> str:
        name = m.group(1)
        if name in table:
            return expand(table[name], table)
        if name in MACROS:
            return MACROS[name]
        raise KeyError(f"unknown macro {{{name}}} in a rewrite pattern")

    return _MACRO.sub(one, pattern)


@dataclass(frozen=True)
class Rule:
    """One row of the table, compiled."""

    id: str
    pattern: re.Pattern[str] | None
    replace: str | None
    fn: Callable[[re.Match[str]], str] | None
    step: Callable[[str], str] | None
    count: int
    when: tuple[re.Pattern[str], ...]
    unless: tuple[re.Pattern[str], ...]
    note: str
    examples: tuple[tuple[str, str], ...]
    #: Sets of lower-case words of which the text must hold one of each for ``pattern`` and every ``when`` to
    #: find anything (:func:`literal_needs`); tested on plain ASCII text only.
    needs: tuple[frozenset[str], ...] = ()

    def could_match(self, text: str) -> bool:
        """False only where the row surely leaves ``text`` as it is: a word its pattern or a ``when`` needs is
        missing (a substring test, much cheaper than the search)."""
        if not self.needs or not text.isascii():
            return True
        low = text.lower()
        return all(any(w in low for w in words) for words in self.needs)

    def __call__(self, text: str) -> str:
        if not self.could_match(text):
            return text
        if not all(w.search(text) for w in self.when) or any(u.search(text) for u in self.unless):
            return text
        if self.step is not None:
            return self.step(text)
        assert self.pattern is not None
        repl: str | Callable[[re.Match[str]], str] = self.fn if self.fn is not None else (self.replace or "")
        return self.pattern.sub(repl, text, count=self.count)


@lru_cache(maxsize=1)
def _raw() -> dict:
    with TABLE.open("rb") as f:
        return tomllib.load(f)


def _table_macros() -> dict[str, str]:
    return dict(_raw().get("macros", {}))


def _compile(row: dict, n: int, macros: dict[str, str]) -> Rule:
    rid = row.get("id")
    if not isinstance(rid, str) or not rid:
        raise ValueError(f"{TABLE.name}: row {n} has no id")
    kinds = [k for k in ("replace", "fn", "step") if k in row]
    if len(kinds) != 1:
        raise ValueError(f"{TABLE.name}: row {rid!r} needs exactly one of replace, fn, step")
    if ("pattern" in row) == ("step" in row):
        raise ValueError(f"{TABLE.name}: row {rid!r}: a step has no pattern, any other row needs one")

    def rxs(key: str) -> tuple[re.Pattern[str], ...]:
        said = row.get(key, ())
        return tuple(re.compile(expand(p, macros)) for p in ([said] if isinstance(said, str) else said))

    fn = _REPLACERS[row["fn"]] if "fn" in row else None
    st = _STEPS[row["step"]] if "step" in row else None
    examples = tuple((str(a), str(b)) for a, b in row.get("examples", ()))
    pattern = re.compile(expand(row["pattern"], macros)) if "pattern" in row else None
    when = rxs("when")
    needs = tuple(n for n in map(literal_needs, ([pattern] if pattern is not None else []) + list(when)) if n)
    return Rule(rid, pattern, row.get("replace"), fn, st, int(row.get("count", 0)), when, rxs("unless"),
                str(row.get("note", "")), examples, needs)


def literal_needs(pattern: re.Pattern[str]) -> frozenset[str]:
    """Lower-case strings of which every ASCII text that ``pattern`` finds anything in holds at least one, once
    lowered; empty where none is known. Read from the pattern's parse tree: a run of literal characters is
    needed where it stands outside any optional part, a branch needs one of its branches' needs, a group or a
    repeat of at least one its own; lookarounds that must fail, classes and back references need nothing.
    Of the needs of one sequence the one with the longest shortest string is kept."""
    try:
        return _needs(list(_sre_parse.parse(pattern.pattern, pattern.flags)))
    except Exception:  # an unforeseen tree: no quick test, the row is always searched
        return frozenset()


def _needs(items: list) -> frozenset[str]:
    best: frozenset[str] = frozenset()
    run = ""

    def keep(cand: frozenset[str]) -> None:
        nonlocal best
        if cand and (not best or min(map(len, cand)) > min(map(len, best))):
            best = cand

    for op, av in items:
        if op is _sre.LITERAL and av < 128:
            run += chr(av).lower()
            continue
        if op is _sre.AT:  # zero-width: the run goes on
            continue
        keep(frozenset([run]) if run else frozenset())
        run = ""
        if op is _sre.SUBPATTERN:
            keep(_needs(list(av[3])))
        elif op is _sre.BRANCH:
            subs = [_needs(list(b)) for b in av[1]]
            keep(frozenset().union(*subs) if all(subs) else frozenset())
        elif op in (_sre.MAX_REPEAT, _sre.MIN_REPEAT, _sre.POSSESSIVE_REPEAT) and av[0] >= 1:
            keep(_needs(list(av[2])))
        elif op is _sre.ASSERT:
            keep(_needs(list(av[1])))
    keep(frozenset([run]) if run else frozenset())
    return best


#: The tables of the file, by name.
TABLES = ("rewrite", "frame", "plain")


@lru_cache(maxsize=len(TABLES))
def rules(table: str = "rewrite") -> tuple[Rule, ...]:
    """Every row of the table ``table``, compiled, in order (ids checked unique across all tables)."""
    from . import rewrite  # registers the named steps and replacers
    del rewrite

    if table not in TABLES:
        raise KeyError(f"no rewrite table {table!r} (there are {', '.join(TABLES)})")
    macros = _table_macros()
    out = tuple(_compile(row, n, macros) for n, row in enumerate(_raw()[table], 1))
    others = {r["id"] for t in TABLES if t != table for r in _raw().get(t, ())}
    seen: set[str] = set()
    for r in out:
        if r.id in seen or r.id in others:
            raise ValueError(f"{TABLE.name}: id {r.id!r} appears twice")
        seen.add(r.id)
    return out


def apply(text: str, table: str = "rewrite") -> str:
    """``text`` after every row of the table ``table``, in order."""
    for rule in rules(table):
        text = rule(text)
    return text


def trace(text: str, table: str = "rewrite") -> list[tuple[str, str]]:
    """The rows that change ``text``, in order, each with the text after it (for debugging a phrasing)."""
    out: list[tuple[str, str]] = []
    for rule in rules(table):
        new = rule(text)
        if new != text:
            out.append((rule.id, new))
        text = new
    return out


@lru_cache(maxsize=1)
def pattern_words(shortest: int = 5) -> frozenset[str]:
    """The words the rows of every table read, taken from their patterns ("required" from "it is
    (?:necessary|needed|required) that"): runs of lower-case letters of ``shortest`` letters or more, a
    letter after a backslash (``\\b``, ``\\s``) and a macro's name (``{HUE}``) being no word. The spelling
    stage may correct a slip into one of them."""
    out: set[str] = set()
    for table in TABLES:
        for row in _raw().get(table, ()):
            for key in ("pattern", "when", "unless"):
                said = row.get(key, ())
                for text in [said] if isinstance(said, str) else said:
                    run = ""
                    for k, ch in enumerate(text + " "):
                        if "a" <= ch <= "z" and not (k and text[k - 1] == "\\"):
                            run += ch
                            continue
                        if len(run) >= shortest:
                            out.add(run)
                        run = ""
    return frozenset(out)
