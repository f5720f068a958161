"""The wire protocol of `max2code serve` (docs/server.md): JSON text frames, version 6, or
MessagePack binary frames when hello asks for them (`enc: "msgpack"`).

Why JSON: the client is a static page with no build step and no library, and a browser parses
JSON natively (and shows it in its developer tools); messages are small because only events
travel, and WebSocket's permessage-deflate compresses what repeats. Numbers are written with
NUMBER_DIGITS significant digits: a segment is re-sent at every change, so its rounding never
accumulates, and 1e-9 relative is far below a pixel.

Client messages are checked here, strictly, before anything else sees them: a frame that is not
a JSON object of a known type with exactly the fields that type allows, with values of the
right types and ranges, and with the next sequence number, is a ProtocolError (the server then
sends an error frame and closes). Nothing from a client is ever evaluated.

MessagePack (the `msgpack` package) is an option a client negotiates in its hello, which is
always JSON text: from the answer on, both directions are binary frames holding exactly the
values the JSON form would (the same maps, keys and rounded numbers), packed; a float is 9
bytes where its JSON text is some 12. Unpacking is bounded (the frame's size, string, array
and map lengths) and refuses extension types; the unpacked value is checked as JSON's is.
"""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass

import msgpack

VERSION = 6   # 2: bodies removed (rm) and added (add); 3: events once per (kind, a, b) with a count;
#               4: segments falling with the world's g in `fall`, without it;
#               5: a segment's 9th number, alpha (angle + omega s + alpha s^2/2);
#               6: its 10th to 12th, the jerks jx, jy, ja (+ j s^3/6: a held body's cubic)
NUMBER_DIGITS = 10
MAX_MESSAGE = 1024          # bytes of one client frame (our own limit: an error frame, then close)
HARD_MAX_MESSAGE = 65536    # the WebSocket library's limit (close 1009 without reading it)
RATE = 60.0                 # client messages per second, sustained
BURST = 120                 # and at once (a token bucket)
KEYS = ("left", "right", "up", "down")
ENCODINGS = ("json", "msgpack")   # hello's enc: the frames after hello (JSON text, MessagePack binary)
ROOM = re.compile(r"[a-z0-9][a-z0-9-]{0,31}")

# close codes (RFC 6455): 1008 policy violation, 1009 too big, 1002 protocol error
CLOSE_POLICY, CLOSE_TOO_BIG, CLOSE_PROTOCOL = 1008, 1009, 1002

# event kinds on the wire: the engine's reported kinds plus the server's own
EVENT_CODES = {"collision": 1, "rest": 2, "wake": 3, "timer": 4, "input": 5, "join": 6,
               "leave": 7, "remove": 8}


class ProtocolError(ValueError):
    """A client message the server refuses; `code` is the close code to use."""

    def __init__(self, reason: str, code: int = CLOSE_POLICY) -> None:
        super().__init__(reason)
        self.reason = reason
        self.code = code


@dataclass(frozen=True)
class Hello:
    seq: int
    room: str | None      # None: the URL's (/ws?room=NAME), else main
    name: str
    play: bool = True     # false: watch only (never given a body)
    events: bool = True   # false: ev messages without their events (the page draws none)
    enc: str = "json"     # the encoding of every frame after hello, both ways (ENCODINGS)


@dataclass(frozen=True)
class Ping:
    seq: int
    id: int
    c: float          # the client's clock when it sent the ping (echoed back)


@dataclass(frozen=True)
class Key:
    seq: int
    body: int
    key: str
    down: bool


@dataclass(frozen=True)
class Point:
    seq: int
    body: int
    x: float
    y: float


Message = Hello | Ping | Key | Point


def _int(v: object, what: str, lo: int, hi: int) -> int:
    if isinstance(v, bool) or not isinstance(v, int) or not lo <= v <= hi:
        raise ProtocolError(f"{what} must be a whole number in {lo}..{hi}")
    return v


def _num(v: object, what: str) -> float:
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
        raise ProtocolError(f"{what} must be a finite number")
    return float(v)


def _str(v: object, what: str, pattern: re.Pattern) -> str:
    if not isinstance(v, str) or not pattern.fullmatch(v):
        raise ProtocolError(f"{what} must match {pattern.pattern}")
    return v


NAME = re.compile(r"[\w .-]{0,32}")
_FIELDS = {
    "hello": {"type", "seq", "v", "room", "name", "play", "events", "enc"},
    "ping": {"type", "seq", "id", "c"},
    "key": {"type", "seq", "body", "key", "down"},
    "point": {"type", "seq", "body", "x", "y"},
}
_REQUIRED = {
    "hello": {"type", "seq", "v"},
    "ping": {"type", "seq", "id", "c"},
    "key": {"type", "seq", "body", "key", "down"},
    "point": {"type", "seq", "body", "x", "y"},
}
_BIG = 2 ** 53


def _reject_constant(name: str) -> float:
    raise ProtocolError(f"{name} is not JSON")


def _no_ext(code: int, data: bytes) -> object:
    raise ProtocolError("MessagePack extension types are not part of the protocol")


def decode(frame: str | bytes, enc: str = "json") -> object:
    """A client frame's value: JSON text, or (enc msgpack) one MessagePack binary value;
    ProtocolError when oversized, of the other kind, or malformed."""
    if enc == "msgpack":
        if not isinstance(frame, bytes):
            raise ProtocolError("text frame: this connection negotiated MessagePack (binary frames)")
        if len(frame) > MAX_MESSAGE:
            raise ProtocolError(f"message larger than {MAX_MESSAGE} bytes", CLOSE_TOO_BIG)
        try:   # (bounded by the frame's size, and nothing but JSON's kinds of value)
            return msgpack.unpackb(frame, raw=False, strict_map_key=True, ext_hook=_no_ext,
                                   max_bin_len=0, max_ext_len=0)
        except ProtocolError:
            raise
        except (ValueError, RecursionError, msgpack.UnpackException):
            raise ProtocolError("not MessagePack") from None   # (ExtraData, StackError, ...)
    if isinstance(frame, bytes):
        raise ProtocolError(f"binary frames are not part of protocol version {VERSION} "
                            "unless hello asks for enc msgpack")
    if len(frame.encode("utf-8", "surrogatepass")) > MAX_MESSAGE:
        raise ProtocolError(f"message larger than {MAX_MESSAGE} bytes", CLOSE_TOO_BIG)
    try:
        return json.loads(frame, parse_constant=_reject_constant)
    except (ValueError, RecursionError) as e:
        if isinstance(e, ProtocolError):
            raise
        raise ProtocolError("not JSON") from None


def parse(frame: str | bytes, expected_seq: int, enc: str = "json") -> Message:
    """One client frame as a message, or ProtocolError: oversized, not JSON text (not
    MessagePack binary, for a connection whose hello asked for it), not an object, unknown
    type or fields, bad values, or a sequence number other than expected_seq (out of order,
    repeated or skipped)."""
    data = decode(frame, enc)
    if not isinstance(data, dict):
        raise ProtocolError("a message must be a JSON object")
    kind = data.get("type")
    if not isinstance(kind, str) or kind not in _FIELDS:
        raise ProtocolError("unknown message type (hello, ping, key, point)")
    keys = set(data)
    if keys - _FIELDS[kind]:
        raise ProtocolError(f"unknown field(s) in {kind}: {', '.join(sorted(keys - _FIELDS[kind]))[:80]}")
    if _REQUIRED[kind] - keys:
        raise ProtocolError(f"{kind} lacks {', '.join(sorted(_REQUIRED[kind] - keys))}")
    seq = _int(data["seq"], "seq", 0, _BIG)
    if seq != expected_seq:
        raise ProtocolError(f"out of order: seq {seq}, expected {expected_seq}")
    if kind == "hello":
        if data["v"] != VERSION or isinstance(data["v"], bool):
            raise ProtocolError(f"protocol version {VERSION} only")
        play, events = data.get("play", True), data.get("events", True)
        if not isinstance(play, bool) or not isinstance(events, bool):
            raise ProtocolError("play and events must be true or false")
        enc = data.get("enc", "json")
        if not isinstance(enc, str) or enc not in ENCODINGS:
            raise ProtocolError(f"enc must be one of {', '.join(ENCODINGS)}")
        return Hello(seq, _str(data["room"], "room", ROOM) if "room" in data else None,
                     _str(data.get("name", ""), "name", NAME), play, events, enc)
    if kind == "ping":
        return Ping(seq, _int(data["id"], "id", 0, _BIG), _num(data["c"], "c"))
    body = _int(data["body"], "body", 0, 2 ** 31 - 1)
    if kind == "key":
        if data["key"] not in KEYS:
            raise ProtocolError(f"key must be one of {', '.join(KEYS)}")
        if not isinstance(data["down"], bool):
            raise ProtocolError("down must be true or false")
        return Key(seq, body, data["key"], data["down"])
    return Point(seq, body, _num(data["x"], "x"), _num(data["y"], "y"))


def number(v: float) -> float | int:
    """A float rounded to NUMBER_DIGITS significant digits (its JSON text is then short)."""
    if v == 0:
        return 0
    r = float(f"{v:.{NUMBER_DIGITS}g}")
    return int(r) if r.is_integer() and abs(r) < 1e15 else r


def encode(message: dict, enc: str = "json") -> str | bytes:
    """Compact JSON text (no spaces), or the same value as MessagePack bytes."""
    if enc == "msgpack":
        return msgpack.packb(message)
    return json.dumps(message, separators=(",", ":"), allow_nan=False)


def error(reason: str, enc: str = "json") -> str | bytes:
    return encode({"type": "error", "reason": reason}, enc)


class RateLimit:
    """A token bucket: RATE messages per second sustained, BURST at once."""

    def __init__(self, rate: float = RATE, burst: int = BURST) -> None:
        self.rate, self.burst = rate, burst
        self.tokens = float(burst)
        self.last: float | None = None

    def allow(self, now: float) -> bool:
        if self.last is not None:
            self.tokens = min(self.burst, self.tokens + (now - self.last) * self.rate)
        self.last = now
        if self.tokens < 1:
            return False
        self.tokens -= 1
        return True
