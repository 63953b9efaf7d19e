"""A `p` or `u` app that talks to a device, or a `p` app that talks to a vehicle or service.

## What it does
Reports a C++ MOOS app whose process name starts with `p` or `u` while its
code does device I/O: a serial-port class (`CMOOSSerialPort`,
`boost::asio::serial_port`, ...), baud-rate setup through termios
(`cfsetispeed`), a device path (`/dev/tty*`, `/dev/can*`, `/dev/usb*`, a
joystick's `/dev/input/js0`, ...), SocketCAN, libusb, or a library that
reaches hardware (libmodbus, a Raspberry Pi's pigpio, wiringPi or libgpiod,
the kernel's I2C and SPI interfaces, the BeagleBone's librobotcontrol), by
the header it includes. A `p` app is also
reported for socket I/O (`socket`, `connect`,
`bind`, `recvfrom`, a socket class, an autopilot link opened with MAVSDK's
`add_any_connection`, a client of the gpsd service: libgps's `gpsmm` or
`gps_open`, a web service reached with libcurl: `curl/curl.h`,
`curl_easy_perform`): a vehicle, a sensor or a service spoken to in a
protocol that is not MOOS. The finding is on the first such use. The app's
own classes are no evidence by their names (`class UdpDecoder : public
CMOOSApp` decodes what another app received), nor is the header of the app's
own class (`pMOOSSerial` including `MOOSSerial.h`): what they do shows in
their calls, includes and strings.

The app's own helper files count too: a C++ file of the app's folder that
never names the MOOS API (a class that opens the port or the link) is read for
the I/O headers it includes (`sys/socket.h`, `termios.h`, a serial-port
library, SocketCAN, libusb, libcurl), for MAVSDK links and for the device
paths it writes outside comments (`#define EVDEV_DIR "/dev/input/by-id/"`),
without being parsed.

## Why is this bad?
The MOOS conventions name processes by what they are: `i` for interface apps
(the apps that have I/O with a device, or non-MOOS communications), `p` for
processes that only work on data from the MOOSDB, `u` for utilities. Someone
reading a mission's Antler block relies on the prefix to know which apps touch
hardware or the outside world (what must run on the vehicle, what can be
simulated).

Not reported: writing log files, a GUI (an app with an FLTK or Qt window, also
when it downloads with libcurl: a viewer fetching its background map), termios
used alone (keyboard input in a terminal), network traffic that carries MOOS
itself (pShare, pMOOSBridge, and any app holding a `CMOOSCommClient` /
`MOOSAsyncCommClient` of another community), and sockets in `u` apps (tools
that talk to a shoreside service).

## Example
```cpp
// pDepthSensor/main.cpp
App.Run("pDepthSensor", mission);
// DepthSensor.cpp
CMOOSSerialPort m_port;            // a p app reading a serial device
```

## How to fix
Rename the process with an `i` prefix (`iDepthSensor`), or move the device
code into its own interface app and keep the `p` app on MOOSDB data.

## Options
- `sockets` (bool, default `true`): also report `p` apps that use sockets
  (other than MOOS bridges). Turn it off for a code base whose `p` apps talk to
  services on purpose.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="C001",
    name="pure-app-does-io",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
    options={"sockets": True},
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import pure_app_does_io

    yield from cpp_findings(ctx, pure_app_does_io, sockets=bool(ctx.options.get("sockets", True)))
