"""A `p` app that talks to hardware (serial ports, termios, `/dev/tty*`, CAN, USB).

## What it does
Reports a C++ MOOS app whose process name starts with `p` while its code does
device I/O: a serial-port class (`CMOOSSerialPort`, `boost::asio::serial_port`,
...), baud-rate setup through termios (`cfsetispeed`), a `/dev/tty*`, `/dev/can*`
or `/dev/usb*` path, SocketCAN or libusb. The finding is on the first such use.

## Why is this bad?
The MOOS conventions name processes by what they are: `i` for instruments (the
apps that talk to sensors and actuators), `p` for processes that only work on
data from the MOOSDB, `u` for utilities. Someone reading a mission's Antler
block relies on the prefix to know which apps touch hardware (what must run on
the vehicle, what can be simulated).

Not reported: writing log files, a GUI, termios used alone (keyboard input in a
terminal), and network traffic that carries MOOS itself (pShare, pMOOSBridge).
Other sockets are reported only with the `sockets` option.

## Example
```cpp
// pDepthSensor/main.cpp
App.Run("pDepthSensor", mission);
// DepthSensor.cpp
CMOOSSerialPort m_port;            // a p app reading a serial device
```

## How to fix
Rename the process with an `i` prefix (`iDepthSensor`), or move the device
code into its own instrument app and keep the `p` app on MOOSDB data.

## Options
- `sockets` (bool, default `false`): also report `p` apps that open sockets
  (other than pShare and pMOOSBridge, whose sockets carry MOOS itself).
"""

from moos_lint.declare import Kind, Scope, rule
from moos_lint.diagnostics import Severity


@rule(
    code="C001",
    name="pure-app-does-io",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
    options={"sockets": False},
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.cpp.checks import pure_app_does_io
    from moos_lint.cpp.rulekit import cpp_findings

    yield from cpp_findings(ctx, pure_app_does_io, sockets=bool(ctx.options.get("sockets")))
