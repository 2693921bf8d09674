"""The exceptions eom raises: each carries eom's message and, where the error is a scene's
value, the key path of that value (``integrator.step``, ``manoeuvre[0].rudder_deg``).

Each class stands for what the command's exit code says of an error:

============================  ==========================================  ===========
class                         what                                        ``eom`` exit
============================  ==========================================  ===========
:class:`SceneError`           a value of the scene that cannot be used    3
:class:`FileError`            a file that cannot be read (also OSError)   4
:class:`RunError`             a run that cannot go on                     5
:class:`OutputError`          what a run gave could not be kept           4
:class:`InternalError`        the model could not be built or proved      1
:class:`ShapeError`           an array of the wrong shape (ValueError)    —
:class:`InvalidValue`         a value the model does not take (NaN)       —
============================  ==========================================  ===========

A run stopped by Ctrl-C raises Python's own :class:`KeyboardInterrupt`.
"""

from __future__ import annotations


class EomError(Exception):
    """Any error eom raises.

    Attributes:
        message: eom's message, as the command prints it.
        key: the key path of the scene's value the error is about, or None.
        file: the scene (or body) file as it was named, or None.
    """

    def __init__(self, message: str, key: str | None = None, file: str | None = None):
        super().__init__(message)
        self.message = message
        self.key = key
        self.file = file

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.message!r}, key={self.key!r}, file={self.file!r})"


class SceneError(EomError):
    """A value of the scene that cannot be used: a wrong type, a value out of range, an
    unknown key, text that is not TOML. ``key`` names the value."""


class FileError(EomError, OSError):
    """A scene or body file that cannot be read."""


class RunError(EomError):
    """A run that cannot go on (gimbal lock, a step too long, a value that is not finite).

    ``result`` is what the scene's runs kept up to there (a :class:`eom.RunResult`) where
    the kind keeps it, else None.
    """

    result = None


class OutputError(EomError):
    """What a run gave could not be kept."""


class InternalError(EomError):
    """The model could not be built or proved: a bug in eom, not in the scene."""


class ShapeError(EomError, ValueError):
    """An array handed to the model whose shape it does not take."""


class InvalidValue(EomError, ValueError):
    """A value the model does not take: NaN or infinity in a state or an input, a point
    that is not finite."""
