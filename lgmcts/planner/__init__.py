"""The planner: tree, selection, simulation step, search loops and policies."""

from .base import Domain
from .policies import METHODS, plan
from .search import SearchOptions, SearchResult
from .step import StepOptions

__all__ = ["METHODS", "Domain", "SearchOptions", "SearchResult", "StepOptions", "plan"]
