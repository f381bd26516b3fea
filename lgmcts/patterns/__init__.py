"""Pattern priors: one module per pattern behind the protocol in :mod:`.base`."""

from .base import BAND, CLEARANCE, CompiledGoal, Context, GoalProgress, Pattern, get, register, registry

__all__ = ["BAND", "CLEARANCE", "CompiledGoal", "Context", "GoalProgress", "Pattern", "get", "register", "registry"]
