"""A headless Chromium that loads ``report.html`` offline (the tests' and docs' page checks): console errors, requests.

Drives the Debian ``chromium`` (``.ci/install-chromium.sh``) with playwright's Python client
(``executable_path``; playwright's own browsers are never downloaded). Every request is
intercepted: the page itself and ``data:`` URLs are allowed, anything else is recorded and
aborted, so a page that needs the network fails its checks instead of fetching.
"""
from __future__ import annotations

import os
import shutil
import tempfile
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

CHROMIUM_FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync")


def chromium_path() -> str | None:
    """The Chromium binary (``$CHROMIUM``, else chromium / chromium-browser on PATH), or None."""
    env = os.environ.get("CHROMIUM")
    if env and os.path.isfile(env):
        return env
    for name in ("chromium", "chromium-browser"):
        p = shutil.which(name)
        if p:
            return p
    return None


@dataclass
class PageLog:
    """What a loaded page did: console errors, page errors, requests allowed and blocked."""

    console_errors: list[str] = field(default_factory=list)
    page_errors: list[str] = field(default_factory=list)
    allowed: list[str] = field(default_factory=list)
    blocked: list[str] = field(default_factory=list)


@contextmanager
def open_page(path, width: int = 1280, height: int = 900):
    """Load the page at ``path`` in a fresh headless Chromium; yields ``(page, log)``."""
    from playwright.sync_api import sync_playwright
    exe = chromium_path()
    if exe is None:
        raise FileNotFoundError("chromium not found: run .ci/install-chromium.sh")
    url = Path(path).resolve().as_uri()
    log = PageLog()
    profile = tempfile.mkdtemp(prefix="lod2energy-chromium-")
    try:
        with sync_playwright() as pw:
            ctx = pw.chromium.launch_persistent_context(
                profile, executable_path=exe, headless=True, args=list(CHROMIUM_FLAGS),
                viewport={"width": width, "height": height}, service_workers="block")
            try:
                def route(r):
                    u = r.request.url
                    if u == url or u.split("#", 1)[0] == url or u.startswith("data:"):
                        log.allowed.append(u[:80])
                        r.continue_()
                    else:
                        log.blocked.append(u)
                        r.abort()
                ctx.route("**/*", route)
                page = ctx.new_page()
                page.on("console", lambda m: log.console_errors.append(m.text) if m.type == "error" else None)
                page.on("pageerror", lambda e: log.page_errors.append(str(e)))
                page.on("request", lambda q: None if (q.url.split("#", 1)[0] == url or q.url.startswith("data:"))
                        else log.blocked.append(q.url))
                page.goto(url, wait_until="load")
                page.wait_for_selector("body[data-ready='1']", timeout=30000)
                yield page, log
            finally:
                ctx.close()
    finally:
        shutil.rmtree(profile, ignore_errors=True)

