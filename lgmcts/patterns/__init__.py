"""Pattern priors: one module per pattern behind the protocol in :mod:`.base`."""

from .base import (
    BAND,
    CLEARANCE,
    MODULES_ENV,
    CompiledGoal,
    Context,
    GoalProgress,
    Pattern,
    load_pattern_modules,
    register,
    registry,
)

__all__ = [
    "BAND",
    "CLEARANCE",
    "MODULES_ENV",
    "CompiledGoal",
    "Context",
    "GoalProgress",
    "Pattern",
    "load_pattern_modules",
    "register",
    "registry",
]
