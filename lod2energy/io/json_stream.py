"""Reading one large JSON document a piece at a time (a CityJSON file's CityObjects, a GeoJSON's
features) with the standard library's parser: what ``json.load`` accepts, and nothing else, but
never the whole document in memory.

A :class:`Scanner` reads the file in chunks; :meth:`Scanner.members` and :meth:`Scanner.items`
walk an object's members / an array's items (the caller reads each value with
:meth:`Scanner.value`, or walks into it), :meth:`Scanner.end` checks that nothing follows.
"""
from __future__ import annotations

import json
import re
from typing import IO, Any, Iterator

_WS = re.compile(r"[ \t\n\r]*")
#: What may still follow a number cut at the chunk's end ("1." of "1.5": the parser took "1").
_NUMBER_TAIL = re.compile(r"[0-9.eE+\-]*")
#: Characters read at a time.
CHUNK = 1 << 20


class StreamError(ValueError):
    """The text is not JSON: ``msg`` and ``lineno`` as :class:`json.JSONDecodeError` gives them."""

    def __init__(self, msg: str, lineno: int):
        super().__init__(f"{msg} at line {lineno}")
        self.msg, self.lineno = msg, lineno


class Scanner:
    """A JSON text file read in chunks of ``chunk`` characters.

    Parameters
    ----------
    f : text file
    chunk : int
    """

    def __init__(self, f: IO[str], chunk: int = CHUNK):
        self.f, self.chunk = f, chunk
        self.buf, self.pos, self.eof, self.lines = "", 0, False, 0
        self._dec = json.JSONDecoder()

    def _fill(self) -> bool:
        if self.eof:
            return False
        data = self.f.read(self.chunk)
        if not data:
            self.eof = True
            return False
        self.lines += self.buf.count("\n", 0, self.pos)
        self.buf = self.buf[self.pos:] + data
        self.pos = 0
        return True

    def _error(self, msg: str) -> StreamError:
        return StreamError(msg, self.lines + self.buf.count("\n", 0, self.pos) + 1)

    def peek(self) -> str:
        """The next character that is not white space ("" at the end of the file)."""
        while True:
            self.pos = _WS.match(self.buf, self.pos).end()
            if self.pos < len(self.buf):
                return self.buf[self.pos]
            if not self._fill():
                return ""

    def expect(self, ch: str) -> None:
        if self.peek() != ch:
            raise self._error(f"Expecting {ch!r}")
        self.pos += 1

    def value(self) -> Any:
        """The next JSON value, whole (as ``json.loads`` gives it)."""
        if not self.peek():
            raise self._error("Expecting value")
        while True:
            try:
                v, end = self._dec.raw_decode(self.buf, self.pos)
            except json.JSONDecodeError as e:
                if self._fill():  # perhaps only cut off by the chunk's end
                    continue
                raise StreamError(e.msg, self.lines + e.lineno) from None
            if _NUMBER_TAIL.fullmatch(self.buf, end) and self._fill():  # a number cut at the chunk's end
                continue
            self.pos = end
            return v

    def members(self) -> Iterator[str]:
        """The keys of the object that starts here; read each one's value before the next."""
        self.expect("{")
        if self.peek() == "}":
            self.pos += 1
            return
        while True:
            if self.peek() != '"':
                raise self._error("Expecting property name enclosed in double quotes")
            key = self.value()
            self.expect(":")
            yield key
            c = self.peek()
            self.pos += 1
            if c == "}":
                return
            if c != ",":
                self.pos -= 1
                raise self._error("Expecting ',' delimiter")

    def items(self) -> Iterator[int]:
        """The indices of the array that starts here; read each item before the next."""
        self.expect("[")
        if self.peek() == "]":
            self.pos += 1
            return
        i = 0
        while True:
            yield i
            i += 1
            c = self.peek()
            self.pos += 1
            if c == "]":
                return
            if c != ",":
                self.pos -= 1
                raise self._error("Expecting ',' delimiter")

    def end(self) -> None:
        """Nothing but white space is left."""
        if self.peek():
            raise self._error("Extra data")
