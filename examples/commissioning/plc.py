#!/usr/bin/python3
"""A soft PLC for the sorting station (station.gdpn.yaml), over Modbus TCP.

It does what a PLC does: every 10 ms it reads its inputs (the photo-eye, the height sensor,
the pusher's stroke), runs its logic once, and writes its outputs (the belt, the pusher).
The logic is a sequence of four steps, as the net on the station's page net_control, except
that the PLC waits for the pusher's stroke where the net waits fixed times:

  RUN      belt on; a box at the eye: tall (its top nearer than 550 mm) -> PUSH, else -> PASS
  PUSH     belt off, pusher out, until it is 690 mm out -> RETRACT
  RETRACT  pusher in, until it is back within 10 mm -> RUN
  PASS     belt on; the eye clear again -> RUN

A step that waits for the pusher longer than 3 s stops the program with an error (a stalled
pusher: try writing a force of 5 N to holding register 2).

Run the station first, then this, in two terminals:

  gdpn run examples/commissioning/station.gdpn.yaml --modbus 5020
  /usr/bin/python3 examples/commissioning/plc.py --port 5020

With --lockstep (and gdpn run ... --lockstep) each scan asks the plant for 10 ms of model
time through the lockstep register instead of waiting 10 ms of wall clock: the run is as
fast as the two can go, and the same every time. The program ends when the plant closes the
connection (the run is over), or with Ctrl-C.

Needs Debian's python3-pymodbus (3.0).
"""
import argparse
import sys
import time

from pymodbus.client import ModbusTcpClient
from pymodbus.exceptions import ConnectionException, ModbusIOException

# the station's io section (station.gdpn.yaml)
EYE = 0            # discrete input: a box breaks the beam
HEIGHT = 0         # input register, mm: from the sensor down to what is below it
STROKE = 1         # input register, mm: how far the pusher is out
BELT, PUSHER = 0, 1  # coils: the belt runs, the pusher goes out
PUSH_SPEED = 0     # holding register, mm/s: the pusher's top speed
LOCKSTEP = 100     # holding register: steps of the model the controller asks for

SCAN = 0.010             # s, the scan period
STEPS_PER_SCAN = 2       # the station's dt is 5 ms
TALL_BELOW_MM = 550      # a tall box's top (750 mm) is 450 mm below the sensor, a short one's 650
OUT_MM, IN_MM = 690, 10  # the pusher's stroke when out (of 700) and when back
STALL_TIME = 3.0         # s, the longest the pusher may take


class Logic:
    """The control program: inputs in, outputs out, once per scan. `now` is the PLC's clock (s)."""

    def __init__(self):
        self.step = "RUN"
        self.since = 0.0
        self.sorted = {"tall": 0, "short": 0}

    def scan(self, now, eye, height_mm, stroke_mm):
        def go(step):
            self.step, self.since = step, now

        if self.step in ("PUSH", "RETRACT") and now - self.since > STALL_TIME:
            raise RuntimeError(f"the pusher stalled in {self.step} at {stroke_mm} mm")
        if self.step == "RUN" and eye:
            tall = height_mm < TALL_BELOW_MM
            self.sorted["tall" if tall else "short"] += 1
            go("PUSH" if tall else "PASS")
        elif self.step == "PUSH" and stroke_mm >= OUT_MM:
            go("RETRACT")
        elif self.step == "RETRACT" and stroke_mm <= IN_MM:
            go("RUN")
        elif self.step == "PASS" and not eye:
            go("RUN")
        belt = self.step in ("RUN", "PASS")
        pusher = self.step == "PUSH"
        return belt, pusher


class PlantGone(Exception):
    """The plant closed the connection: its run is over."""


def check(reply, what):
    if isinstance(reply, ModbusIOException):
        raise PlantGone()
    if reply.isError():
        raise RuntimeError(f"{what}: {reply}")
    return reply


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--host", default="127.0.0.1")
    ap.add_argument("--port", type=int, default=502)
    ap.add_argument("--lockstep", action="store_true",
                    help="ask the plant for each scan's 10 ms instead of waiting for the wall clock")
    ap.add_argument("--quiet", "-q", action="store_true", help="print nothing but errors")
    args = ap.parse_args()

    client = ModbusTcpClient(args.host, port=args.port, timeout=5)
    for _ in range(50):  # the plant may still be starting
        if client.connect():
            break
        time.sleep(0.1)
    else:
        print(f"plc: error: no Modbus server at {args.host}:{args.port}", file=sys.stderr)
        return 1

    logic = Logic()
    scans = overruns = 0
    worst = 0.0
    start = time.monotonic()
    try:
        check(client.write_register(PUSH_SPEED, 800), "set the pusher's speed")
        while True:
            began = time.monotonic()
            now = scans * SCAN if args.lockstep else began - start
            eye = check(client.read_discrete_inputs(EYE, 1), "read the eye").bits[0]
            height, stroke = check(client.read_input_registers(HEIGHT, 2), "read the sensors").registers
            belt, pusher = logic.scan(now, eye, height, stroke if stroke < 0x8000 else stroke - 0x10000)
            check(client.write_coils(BELT, [belt, pusher]), "write the outputs")
            scans += 1
            if args.lockstep:
                check(client.write_register(LOCKSTEP, STEPS_PER_SCAN), "ask for a scan's steps")
                continue
            took = time.monotonic() - began
            worst = max(worst, took)
            wait = start + scans * SCAN - time.monotonic()
            if wait > 0:
                time.sleep(wait)
            else:
                overruns += 1
    except (PlantGone, ConnectionException, OSError):
        pass  # the run is over and the plant has gone
    except RuntimeError as e:  # a request refused (the io map and this program disagree), a stall
        print(f"plc: error: {e}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        pass
    finally:
        client.close()
    if not args.quiet:
        print(f"plc: {scans} scans; sorted {logic.sorted['tall']} tall and {logic.sorted['short']} short boxes"
              + ("" if args.lockstep else f"; slowest scan {worst * 1000:.1f} ms, {overruns} overruns"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
