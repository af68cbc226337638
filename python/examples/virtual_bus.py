#!/usr/bin/env python3
"""A virtual keypad and a controller on python-can's `virtual` interface: no hardware.

The controller (powerkey.Controller) finds the keypad by its boot-up, sets it up (its heartbeat
and the configuration list: LED brightness 30h), starts it with NMT; when key 3 is pressed on
the virtual keypad (powerkey.VirtualKeypad) the controller lights that key green, and the keypad
shows it. The host reads the bus through a python-can Notifier and a powerkey.Listener, which
decodes every frame; each line printed is the library's description of one frame.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/virtual_bus.py [--model pkp2400]

Exits 0 when the keypad shows the key green, 1 otherwise (ctest runs it: python_virtual_bus).
"""

import argparse
import os
import sys
import time

import can

import powerkey


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--model", default="pkp2400", help="a model name (powerkey.names('model'))")
    ap.add_argument("--node", type=lambda s: int(s, 0), default=0x15, help="node id (0x15)")
    ap.add_argument("--key", type=int, default=3, help="the key to press (3)")
    ap.add_argument("--timeout", type=float, default=10.0, help="give up after seconds (10)")
    args = ap.parse_args()

    # Two ends of one virtual bus: what one sends, the other receives.
    channel = f"powerkey-example-{os.getpid()}"
    keypad_bus = can.Bus(interface="virtual", channel=channel)
    host_bus = can.Bus(interface="virtual", channel=channel)

    keypad = powerkey.VirtualKeypad(model=args.model, node=args.node)
    controller = powerkey.Controller(
        model=args.model,
        node=args.node,
        configuration=[powerkey.message("sdo_write", object="led_brightness", level=0x30)],
        keypad_heartbeat=100,  # written to the keypad's 1017h during the setup
        lost_after=1000,  # silent this long: lost (10 heartbeats; a loaded CI machine may stall)
    )
    listener = powerkey.Listener(model=args.model, node=args.node)
    notifier = can.Notifier(host_bus, [listener])

    start = time.monotonic()

    def now():
        return int((time.monotonic() - start) * 1000)

    def show(who, msg):
        try:
            text = powerkey.decode(msg, model=args.model, node=args.node).describe()
        except powerkey.DecodeError as e:
            text = f"({e.code})"
        data = bytes(msg.data).hex().upper()
        print(f"{now():6d} ms  {who:10s} {msg.arbitration_id:03X}#{data:16s} {text}")

    keypad.power_on(now())
    press_at = None  # when someone presses the key: a while after the controller is ready
    ok = False
    try:
        while now() < args.timeout * 1000:
            # The keypad: every frame of the bus, its timers, what it sends.
            while (msg := keypad_bus.recv(timeout=0)) is not None:
                keypad.receive(msg, now())
            keypad.advance(now())
            for f in keypad.transmit_all():
                keypad_bus.send(f)

            # The host: the frames the Notifier delivered, decoded by the Listener.
            item = listener.get_message(timeout=0.002)
            while item is not None:
                msg, event = item
                show("keypad", msg)
                controller.step(msg, now())
                item = listener.get_message(timeout=0)
            controller.tick(now())
            for f in controller.frames():
                show("controller", f)
                host_bus.send(f)
            for e in controller.events():
                detail = e.what if e.kind.startswith("sdo") else e.key if e.key else ""
                print(f"{now():6d} ms  event      {e.kind} {detail}")
                if e.kind == "ready" and press_at is None:
                    press_at = now() + 100
                elif e.kind == "key_pressed":
                    controller.set_led(e.key, "green")

            if press_at is not None and now() >= press_at and not keypad.keys:
                keypad.press(args.key, now())  # sends a key state once the keypad is started
            if args.key in keypad.led_on["green"]:
                ok = True
                break
    finally:
        notifier.stop()
        keypad_bus.shutdown()
        host_bus.shutdown()

    print(f"keypad: {keypad.state}, LEDs on {keypad.led_on}, brightness {keypad.brightness:02X}h")
    if not ok:
        print(f"key {args.key} was not lit within {args.timeout} s", file=sys.stderr)
        return 1
    if keypad.brightness != 0x30:
        print("the configuration list did not reach the keypad", file=sys.stderr)
        return 1
    print(f"key {args.key} pressed and lit green")
    return 0


if __name__ == "__main__":
    sys.exit(main())
