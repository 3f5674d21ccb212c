"""A minimal Chrome DevTools Protocol client over ``--remote-debugging-pipe`` (standard library only).

Chromium started with ``--remote-debugging-pipe`` reads protocol commands from file
descriptor 3 and writes responses and events to file descriptor 4, each message one JSON
object followed by a NUL byte (the transport Playwright and Puppeteer use for local
browsers). Compared with ``--remote-debugging-port`` this needs no TCP port (nothing to
collide with, nothing listening on the machine) and no WebSocket library.

Only what the browser test needs is here: start and stop the browser, open a page target,
send a command and wait for its answer, and collect the events of that page.
"""

from __future__ import annotations

import base64
import fcntl
import json
import os
import select
import shutil
import subprocess
import tempfile
import time
from pathlib import Path

# The flags the machine's notes give for Chromium here (root, no network but the package
# registries): no sandbox as root, no GPU, no background traffic to Google's services.
#: JPEG screenshots: the quality (text stays sharp to read) and the format's largest height.
JPEG_QUALITY = 85
JPEG_MAX_HEIGHT = 65_000

CHROMIUM_FLAGS = (
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
    "--no-default-browser-check",
    "--disable-quic",
    "--disable-extensions",
    "--hide-scrollbars",
    "--mute-audio",
    "--force-device-scale-factor=1",
)


class CDPError(RuntimeError):
    """An error answer of the browser, or a browser that stopped answering."""


def find_chromium() -> str | None:
    """``$ROTORLYAP_CHROMIUM``, else the first of chromium, chromium-browser, google-chrome on PATH."""
    env = os.environ.get("ROTORLYAP_CHROMIUM")
    if env:
        return env if Path(env).is_file() else None
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


class Browser:
    """One headless Chromium, driven over the DevTools pipe."""

    def __init__(self, executable: str, *, timeout: float = 60.0, extra_flags: tuple = ()):
        self.timeout = timeout
        self._profile = tempfile.mkdtemp(prefix="rotorlyap-chromium-")
        to_browser_r, self._to_browser = os.pipe()
        self._from_browser, from_browser_w = os.pipe()

        def child_fds() -> None:  # runs in the child between fork and exec
            # Move both ends above 10 first, so that the dup2 onto 3 and 4 cannot clobber
            # one with the other whatever numbers the pipes got in the parent.
            r = fcntl.fcntl(to_browser_r, fcntl.F_DUPFD, 10)
            w = fcntl.fcntl(from_browser_w, fcntl.F_DUPFD, 10)
            os.dup2(r, 3)
            os.dup2(w, 4)

        cmd = [executable, *CHROMIUM_FLAGS, *extra_flags, f"--user-data-dir={self._profile}",
               "--remote-debugging-pipe", "about:blank"]
        self._stderr = tempfile.TemporaryFile()
        self.proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                     stderr=self._stderr, preexec_fn=child_fds, pass_fds=(3, 4),
                                     close_fds=True)
        os.close(to_browser_r)
        os.close(from_browser_w)
        self._buffer = b""
        self._next_id = 0
        self._events: list[dict] = []
        self.version = self.send("Browser.getVersion")["product"]

    # -- transport -----------------------------------------------------------------------
    def _write(self, message: dict) -> None:
        data = json.dumps(message).encode() + b"\0"
        while data:
            n = os.write(self._to_browser, data)
            data = data[n:]

    def _read_message(self, deadline: float) -> dict:
        while b"\0" not in self._buffer:
            left = deadline - time.monotonic()
            if left <= 0:
                raise CDPError("timed out waiting for the browser")
            ready, _, _ = select.select([self._from_browser], [], [], left)
            if not ready:
                continue
            chunk = os.read(self._from_browser, 1 << 20)
            if not chunk:
                raise CDPError(f"the browser closed the pipe (exit code {self.proc.poll()}): {self.stderr_tail()}")
            self._buffer += chunk
        raw, self._buffer = self._buffer.split(b"\0", 1)
        return json.loads(raw)

    def send(self, method: str, params: dict | None = None, *, session: str | None = None,
             timeout: float | None = None) -> dict:
        """Send one command and return its ``result``; events that arrive meanwhile are kept."""
        self._next_id += 1
        msg_id = self._next_id
        message = {"id": msg_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        self._write(message)
        deadline = time.monotonic() + (timeout or self.timeout)
        while True:
            reply = self._read_message(deadline)
            if reply.get("id") == msg_id:
                if "error" in reply:
                    raise CDPError(f"{method}: {reply['error']}")
                return reply.get("result", {})
            if "method" in reply:
                self._events.append(reply)

    def wait_event(self, method: str, *, session: str | None = None, timeout: float | None = None) -> dict:
        """Wait for (and consume) the first event ``method`` of ``session``."""
        deadline = time.monotonic() + (timeout or self.timeout)
        while True:
            for k, ev in enumerate(self._events):
                if ev["method"] == method and (session is None or ev.get("sessionId") == session):
                    return self._events.pop(k)
            self._events.append(self._read_message(deadline))

    def drain_events(self, session: str | None = None) -> list[dict]:
        """Return and forget the events collected so far (of one session, if given)."""
        keep, out = [], []
        for ev in self._events:
            (out if session is None or ev.get("sessionId") == session else keep).append(ev)
        self._events = keep
        return out

    # -- pages ---------------------------------------------------------------------------
    def new_page(self, *, width: int = 1280, height: int = 900) -> "Page":
        target = self.send("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = self.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        page = Page(self, target, session)
        for domain in ("Page", "Runtime", "Network"):
            self.send(f"{domain}.enable", session=session)
        page.set_viewport(width, height)
        return page

    def stderr_tail(self, n: int = 2000) -> str:
        self._stderr.seek(0)
        return self._stderr.read().decode(errors="replace")[-n:]

    def close(self) -> None:
        try:
            if self.proc.poll() is None:
                try:
                    self.send("Browser.close", timeout=10)
                except (CDPError, OSError):
                    pass
                try:
                    self.proc.wait(timeout=10)
                except subprocess.TimeoutExpired:
                    self.proc.kill()
                    self.proc.wait(timeout=10)
        finally:
            for fd in (self._to_browser, self._from_browser):
                try:
                    os.close(fd)
                except OSError:
                    pass
            self._stderr.close()
            shutil.rmtree(self._profile, ignore_errors=True)


# Wait until no CSS transition or animation runs (at most 5 s), then two animation frames.
_SETTLE = """(async () => {
  const t0 = performance.now();
  const frame = () => new Promise(r => requestAnimationFrame(() => r()));
  await frame();
  while (document.getAnimations().some(a => a.playState === 'running') && performance.now() - t0 < 5000) {
    await new Promise(r => setTimeout(r, 50));
  }
  await frame(); await frame();
  return performance.now() - t0;
})()"""


class Page:
    """One tab, attached in flat mode (commands carry its session id)."""

    def __init__(self, browser: Browser, target: str, session: str):
        self.browser, self.target, self.session = browser, target, session
        self.width, self.height = 1280, 900

    def send(self, method: str, params: dict | None = None, **kw) -> dict:
        return self.browser.send(method, params, session=self.session, **kw)

    def set_viewport(self, width: int, height: int) -> None:
        self.width, self.height = width, height
        self.send("Emulation.setDeviceMetricsOverride",
                  {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False})

    def navigate(self, url: str, *, timeout: float | None = None) -> list[dict]:
        """Load ``url``, wait for its load event; return the page's events up to then."""
        self.browser.drain_events(self.session)
        reply = self.send("Page.navigate", {"url": url})
        if reply.get("errorText"):
            raise CDPError(f"navigation to {url} failed: {reply['errorText']}")
        self.browser.wait_event("Page.loadEventFired", session=self.session, timeout=timeout)
        return self.browser.drain_events(self.session)

    def evaluate(self, expression: str, *, timeout: float | None = None):
        """Evaluate JavaScript (awaiting a promise) and return its value as JSON data."""
        reply = self.send("Runtime.evaluate", {"expression": expression, "awaitPromise": True,
                                               "returnByValue": True}, timeout=timeout)
        if "exceptionDetails" in reply:
            raise CDPError(f"JavaScript error: {reply['exceptionDetails']}")
        return reply["result"].get("value")

    def screenshot(self, path: Path, *, max_height: int = 200_000) -> tuple[int, int]:
        """Save an image of the whole page (up to ``max_height`` CSS pixels); return its size.
        The file's suffix chooses the format: ``.png``, or ``.jpg`` (JPEG of quality
        :data:`JPEG_QUALITY`: Chromium encodes a tall page's JPEG in under half the time of its
        PNG, measured 1.2 s against 2.8 s for a 1280 x 32,000 px page; a JPEG is at most
        :data:`JPEG_MAX_HEIGHT` px tall).

        The viewport is made as tall as the page, the page is left to settle (CSS transitions
        the resize starts, two animation frames), the viewport is captured, and the viewport
        is put back. (``captureBeyondViewport`` alone was seen to draw the content of a
        tall page shifted sideways while the theme's transitions ran.)
        """
        width, height0 = self.width, self.height
        jpeg = Path(path).suffix.lower() in (".jpg", ".jpeg")
        if jpeg:
            max_height = min(max_height, JPEG_MAX_HEIGHT)
        size = self.send("Page.getLayoutMetrics")["cssContentSize"]
        height = int(min(max(size["height"], 1), max_height))
        self.set_viewport(width, height)
        try:
            self.evaluate(_SETTLE, timeout=30)
            size = self.send("Page.getLayoutMetrics")["cssContentSize"]
            if int(size["height"]) != height and int(size["height"]) <= max_height:
                height = int(size["height"])  # the layout changed with the viewport
                self.set_viewport(width, height)
                self.evaluate(_SETTLE, timeout=30)
            data = self.send("Page.captureScreenshot", {
                **({"format": "jpeg", "quality": JPEG_QUALITY} if jpeg else {"format": "png"}), "fromSurface": True,
                "clip": {"x": 0, "y": 0, "width": width, "height": height, "scale": 1},
            }, timeout=120)["data"]
        finally:
            self.set_viewport(width, height0)
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(base64.b64decode(data))
        return width, height

    def close(self) -> None:
        self.browser.send("Target.closeTarget", {"targetId": self.target})
