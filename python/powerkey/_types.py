"""The plain Python types of the powerkey package: errors, frames, accessor results, events.

The extension module (_powerkey) imports this module when it loads and builds its results with
these types, so they exist once, in Python.
"""

from collections import namedtuple

try:  # python-can is optional for decoding; frames come back as can.Message when it is there
    import can as _can
except ImportError:  # pragma: no cover - Debian's python3-can is a test dependency
    _can = None


class Error(Exception):
    """A refusal of the library. `code` names the library's errc ("value_out_of_range", ...;
    docs/errors.md), or is None where the library has no code (an unknown kind or field name)."""

    def __init__(self, message, code=None):
        super().__init__(message)
        self.code = code


class DecodeError(Error, ValueError):
    """decode() refused the frame: `code` is the errc decode returned."""


class EncodeError(Error, ValueError):
    """encode() refused the message (or a field value is outside its range): `code` is the errc."""


class ArgumentError(Error, ValueError):
    """An argument names nothing: an unknown model, kind, field or enum name."""


# A frame without python-can: the attribute names of can.Message.
Frame = namedtuple("Frame", "arbitration_id data is_extended_id")

# The LED map a frame states (accessors.hpp led_map_update): `map` and `covered` are dicts
# {"red": [..], "green": [..], "blue": [..]} of LED numbers; LEDs outside `covered` keep theirs.
LedMapUpdate = namedtuple("LedMapUpdate", "map covered")

# What a frame sets of the backlight: its level (0..63) and/or its colour name; None: not set.
BacklightUpdate = namedtuple("BacklightUpdate", "level colour")

# What one frame meant to a Session (session.hpp session_event).
SessionEvent = namedtuple(
    "SessionEvent",
    "function node message error sdo request upload_done text upload_error new_node new_protocol "
    "new_address",
)

# What a Controller tells the application (controller.hpp controller_event).
ControllerEvent = namedtuple("ControllerEvent", "kind key node origin step what value")


def to_frame(arbitration_id, data, is_extended_id):
    """A frame the library built, as a can.Message (a Frame when python-can is missing)."""
    if _can is None:
        return Frame(arbitration_id, bytes(data), is_extended_id)
    return _can.Message(
        arbitration_id=arbitration_id,
        data=data,
        is_extended_id=is_extended_id,
        dlc=len(data),
    )
