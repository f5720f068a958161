"""`max2code serve`: the engine authoritative on a server, thin clients in browsers.

protocol.py  the wire format (version 4) and the checks every client message passes
wire.py      a World as the client sees it: shapes, styles, motion segments
room.py      one world, its clients, the loop that sleeps between events
app.py       rooms, the WebSocket endpoint and the page (websockets)
static/      the client page (plain JavaScript, a canvas)

docs/server.md describes the protocol and the design.
"""
