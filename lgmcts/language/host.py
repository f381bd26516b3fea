"""What each part of the rules parser may use of the assembled parser, for the type checker.

The rules parser (:class:`.rules._Parser`) is put together from one mixin per
concern (:mod:`.passes`, :mod:`.selection`, :mod:`.arrangements`,
:mod:`.framing`, :mod:`.assembly`); each uses the parser's state and some
steps of the others. :class:`ParserHost` declares them, and each mixin
derives from it only while type checking (at run time it derives from
``object``), so mypy checks every use against one declaration and every
step's definition against its declared signature.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ..formats import GoalSpec, SceneSpec
    from .assembly import _Pending
    from .matcher import PatternInfo, PatternMatcher
    from .rules import RulesOptions, _State
    from .vocabulary import Choice, Mention, Vocabulary

__all__ = ["ParserHost"]


class ParserHost:
    """The attributes of the assembled parser and the steps one part of it calls in another."""

    spec: SceneSpec
    vocab: Vocabulary
    matcher: PatternMatcher
    options: RulesOptions
    infos: dict[str, PatternInfo]
    key_vocab: frozenset[str]
    state: _State
    fired: list[str]
    _cat_words: frozenset[str]
    _below_first: bool
    _order_by: str | None
    _chain: int | None
    _implicit: tuple | None
    _it_beside: bool
    _first: Mention | None
    _them_again: bool
    _slips: bool
    _named_in: list[tuple[tuple[str, ...], list[Mention]]]
    _said: str
    _measures: list
    _poses: list
    _measured: set[int]
    _last_read: _Pending | None

    if TYPE_CHECKING:
        # passes
        def _arrangement_refs(self, words: tuple[str, ...]) -> tuple[str, ...]: ...
        # selection
        def _find(self, words: tuple[str, ...], key_vocab: Any = None) -> list[Mention]: ...
        def _every_match(self, m: Mention) -> list[int]: ...
        def _select(self, m: Mention) -> list[int] | Choice: ...
        def _select_group(self, group: list[Mention]) -> list: ...
        def _select_noting(self, mentions: Any) -> list[int | Choice]: ...
        def _note_nouns(self, mentions: Any) -> None: ...
        def _object_word(self, w: str) -> bool: ...
        def _names_shape(self, m: Mention, shape: _Pending) -> bool: ...
        def _request_word(self, w: str) -> bool: ...
        def _content_word(self, w: str) -> bool: ...
        def _names_objects(self, part: list[str]) -> bool: ...
        def _unknown_nouns(self, words: tuple[str, ...], mentions: list[Mention]) -> list[str]: ...
        def _unknown_objects(self, words: tuple[str, ...], rest: list[int], mentions: list[Mention]) -> None: ...
        # arrangements
        def _word_kinds(self) -> tuple[frozenset[str], frozenset[str]]: ...
        def _free_word(self, w: str) -> bool: ...
        def _match(self, phrase: str, text: str, allowed: frozenset[str]) -> Any: ...
        def _shape(self, pattern: str, sels: Any, words: Any, gaps: Any, text: str, phrase_words: Any, *,
                   vertical: str | None = None, roles: dict | None = None, defer_min: bool = False) -> _Pending: ...
        def _dinner_at(self, words: tuple[str, ...]) -> int | None: ...
        def _dinner(self, words: tuple[str, ...]) -> list[_Pending] | None: ...
        # assembly
        def _finish(self, pending: list[_Pending]) -> GoalSpec: ...
