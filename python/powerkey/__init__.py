"""powerkey: every CAN frame of Blink Marine PowerKey keypads, for python-can test benches.

The C++ library (include/powerkey/) through pybind11, with the vocabulary of the C++ API and of
the `powerkey` tool's JSON (docs/python.md):

    import can, powerkey
    m = powerkey.decode(can.Message(arbitration_id=0x195, data=bytes.fromhex("040000002A"),
                                    is_extended_id=False), model="pkp2400")
    m.kind, m.keys, m.to_dict()          # 'key_state', [3], {'keys': [3], 'tick': 42}
    powerkey.encode("led_on", model="pkp2400", green=[3])   # can.Message 215#0004000000000000
"""

import queue as _queue

from ._types import (  # noqa: F401  (the package's public names)
    ArgumentError,
    BacklightUpdate,
    ControllerEvent,
    DecodeError,
    EncodeError,
    Error,
    Frame,
    LedMapUpdate,
    SessionEvent,
    _can,
)
from . import _powerkey
from ._powerkey import Message, Model, kinds, model_info, names, parse_model  # noqa: F401

__all__ = [
    "ArgumentError", "BacklightUpdate", "Controller", "ControllerEvent", "DecodeError",
    "EncodeError", "Error", "Frame", "LedMapUpdate", "Message", "Model", "Session",
    "SessionEvent", "VirtualKeypad", "address_change", "backlight_change", "key_change",
    "led_brightness_level", "decode", "encode", "encode_frame", "kinds", "led_blink_map",
    "led_on_map", "message", "model_info", "names", "reported_nmt_state", "node_id_change",
    "parse_model", "pressed_keys", "skipped_kind",
]
if _can is not None:
    __all__.append("Listener")

DEFAULT_NODE = 0x15  # as delivered (canopen::default_node_id)


def decode(msg_or_id, data=None, *, model, node=DEFAULT_NODE, extended=None, address=None):
    """The message a frame carries, for keypad `model` at `node` (decode(frame, node, model)).

    msg_or_id is a can.Message (or anything with arbitration_id, data, is_extended_id), or an
    identifier with `data` the bytes; `extended` defaults to id > 7FFh. `node` is a number or
    the tool's text ("15h", "0x15"). An extended frame is a J1939 one (kinds "j1939_..."), of
    any keypad address, or of the keypad at `address` (1..0xFD, 70h's range, or the tool's text "21h") only.
    Raises DecodeError whose `code` is the library's errc ("wrong_id", "reserved_not_zero", ...);
    a remote, CAN FD or error frame is "unexpected_frame".
    """
    return _powerkey.decode(msg_or_id, data, model=model, node=node, extended=extended,
                            address=address)


def message(kind, *, model=None, node=None, **fields):
    """A message of `kind` with `fields` (the tool's names and JSON values), not yet encoded:
    the others keep their defaults, an NMT `target` defaults to `node`. For
    Controller(configuration=[...]) and encode()."""
    return _powerkey.message(kind, model=model, node=node, fields=fields)


def encode(kind, *, model=None, node=None, address=None, **fields):
    """The frame of a message, as a can.Message (encode(node, model, message)).

    `kind` is a kind name with its fields as keywords (encode("led_on", model="pkp2400",
    green=[3]); also "led-on", green="3", as the tool takes them), or a Message (then model and
    node default to the message's own). Raises EncodeError with the errc and the tool's words
    ("led_on: red: [5] is more than a pkp2200 takes (1..4)"), ArgumentError for an unknown kind,
    field or model.
    """
    if isinstance(kind, Message):
        if fields:
            raise ArgumentError("encode(Message): give the fields in the message", None)
        return _powerkey.encode_frame(kind, model=model, node=node, address=address)
    if model is None:
        raise ArgumentError("encode: give model=", None)
    n = DEFAULT_NODE if node is None else node
    return _powerkey.encode_frame(message(kind, node=n, **fields), model=model, node=n,
                                  address=address)


def encode_frame(kind, *, model=None, node=None, address=None, **fields):
    """encode(), as a plain (id, data, extended) tuple."""
    f = encode(kind, model=model, node=node, address=address, **fields)
    return f.arbitration_id, bytes(f.data), f.is_extended_id


# --- the accessors (accessors.hpp), as functions too -------------------------------------------

def pressed_keys(m):
    """The pressed keys a key-state PDO, a read of the keys object or a J1939 heartbeat states
    (a J1939 key contact state: its one key when pressed, [] when released), else None."""
    return m.pressed_keys()


def key_change(m, model=None):
    """{'pressed': [...], 'covered': [...]}: the keys a message states and which are pressed
    (a J1939 key contact state covers its one key), else None."""
    return m.key_change(model)


def address_change(m):
    """The J1939 source address a message (command 70h) moves the keypad to, else None."""
    return m.address_change()


def led_on_map(m, model=None):
    """The LED-on map a message states (LedMapUpdate of map and covered), else None."""
    return m.led_on_map(model)


def led_blink_map(m, model=None):
    """The LED-blink map a message states (LedMapUpdate), else None."""
    return m.led_blink_map(model)


def led_brightness_level(m):
    """The key LED level 0..63 a message sets, else None."""
    return m.led_brightness_level()


def backlight_change(m):
    """What a message sets of the backlight (BacklightUpdate of level and colour), else None."""
    return m.backlight_change()


def node_id_change(m):
    """The node id a message moves the keypad to, else None."""
    return m.node_id_change()


def reported_nmt_state(m):
    """The NMT state a heartbeat or boot-up reports ("operational", ...), else None."""
    return m.reported_nmt_state()


def skipped_kind(msg):
    """"remote frame", "CAN FD frame" or "error frame" (the tool's names for what it counts and
    skips), or None for a classic data frame."""
    if getattr(msg, "is_error_frame", False):
        return "error frame"
    if getattr(msg, "is_remote_frame", False):
        return "remote frame"
    if getattr(msg, "is_fd", False):
        return "CAN FD frame"
    return None


# --- the roles, stepped with frames and a time in ms --------------------------------------------

class Session(_powerkey.Session):
    """Follows a bus log frame by frame (session.hpp): decodes for the keypad's current node,
    pairs SDO requests and replies, runs segmented uploads, follows node-id changes.

        s = powerkey.Session(model="pk1000")
        e = s.step(msg)      # SessionEvent: e.message (a Message or None), e.error, e.sdo, ...
    """

    def step(self, msg_or_id, data=None, *, extended=None):
        return SessionEvent(**super().step(msg_or_id, data, extended=extended))


class VirtualKeypad(_powerkey.VirtualKeypad):
    """A keypad in software (behaviour/virtual_keypad.hpp), stepped by the caller:

        k = powerkey.VirtualKeypad(model="pkp2400")
        k.power_on(t); k.receive(msg, t); k.advance(t); k.press(3, t)
        for f in k.transmit_all(): bus.send(f)

    Times are milliseconds on a wrapping 32-bit counter.
    """

    def transmit_all(self):
        """Every frame the keypad wants to send, oldest first (can.Message)."""
        out = []
        while (f := self.transmit()) is not None:
            out.append(f)
        return out


class Controller(_powerkey.Controller):
    """The host side of one keypad (behaviour/controller.hpp): finds it, sets it up, starts it,
    keeps its LEDs, turns its key states into events.

        c = powerkey.Controller(model="pkp2400", configuration=[powerkey.message(...)])
        c.step(msg, t) or c.tick(t); frames = c.frames(); events = c.events()
    """

    def poll(self):
        e = super().poll()
        return None if e is None else ControllerEvent(**e)

    def frames(self):
        """Every frame the controller wants to send, oldest first (can.Message)."""
        out = []
        while (f := self.next_frame()) is not None:
            out.append(f)
        return out

    def events(self):
        """Every event waiting, oldest first (ControllerEvent)."""
        out = []
        while (e := self.poll()) is not None:
            out.append(e)
        return out


if _can is not None:

    class Listener(_can.Listener):
        """A python-can Listener that decodes what a Notifier delivers through a Session.

        Each frame becomes (can.Message, SessionEvent): passed to `callback` when one is given
        (on the Notifier's thread), else queued for get_message(). Remote, CAN FD and error
        frames carry no keypad message: as the tool does, they are counted by kind in
        `skipped` ({"remote frame": 2, ...}), not decoded.

            listener = powerkey.Listener(model="pkp2400")
            notifier = can.Notifier(bus, [listener])
            msg, event = listener.get_message(timeout=1.0)
        """

        def __init__(self, *, model, node=DEFAULT_NODE, callback=None):
            super().__init__()
            self.session = Session(model=model, node=node)
            self.callback = callback
            self.skipped = {}
            self._queue = _queue.Queue()

        def on_message_received(self, msg):
            kind = skipped_kind(msg)
            if kind is not None:
                self.skipped[kind] = self.skipped.get(kind, 0) + 1
                return
            event = self.session.step(msg)
            if self.callback is not None:
                self.callback(msg, event)
            else:
                self._queue.put((msg, event))

        def get_message(self, timeout=0.5):
            """The next (can.Message, SessionEvent), or None after `timeout` seconds."""
            try:
                return self._queue.get(timeout=timeout)
            except _queue.Empty:
                return None

        def stop(self):
            pass
