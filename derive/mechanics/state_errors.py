"""Why a state cannot be found: the file's fault (StateError), or an engine limit (StateLimit)."""


class StateError(ValueError):
    """The state cannot be reached or does not fit the constraints (the file's fault)."""


class StateLimit(StateError):
    """A state derive cannot yet find (an engine limit, not the file's fault)."""


class Curved(StateLimit):
    """A motion of several degrees of freedom that is no straight line in its coordinates."""
