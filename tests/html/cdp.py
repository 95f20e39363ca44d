# SPDX-License-Identifier: BSD-3-Clause
"""A small client of Chromium's DevTools protocol over --remote-debugging-pipe
(file descriptors 3 and 4, messages ending in a NUL byte): no websocket, no
browser download, Debian's chromium headless. Used by tests/html/browser.py."""
import base64
import json
import os
import shutil
import subprocess
import tempfile
import time


def find_chromium():
    # Debian's /usr/bin/chromium is a shell launcher; the binary itself keeps
    # the pipe's descriptors as given
    if os.access("/usr/lib/chromium/chromium", os.X_OK):
        return "/usr/lib/chromium/chromium"
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


class Browser:
    """One headless browser; .page() opens a tab with its own session."""

    def __init__(self, exe=None, timeout=60):
        self.exe = exe or find_chromium()
        if not self.exe:
            raise RuntimeError("no chromium on PATH (tools/deps.sh --tests installs it)")
        self.timeout = timeout
        self.profile = tempfile.mkdtemp(prefix="bgdraw-chromium-")
        self._log = open(os.path.join(self.profile, "stderr.txt"), "w")
        to_browser_r, self._w = os.pipe()
        self._r, from_browser_w = os.pipe()
        # the browser reads fd 3 and writes fd 4 (dup2 leaves them inheritable;
        # Python makes every other descriptor non-inheritable, so close_fds=False)
        def child_fds():
            os.dup2(to_browser_r, 3)
            os.dup2(from_browser_w, 4)
        args = [self.exe, "--headless=new", "--no-sandbox", "--disable-gpu", "--remote-debugging-pipe",
                "--user-data-dir=" + self.profile, "--no-first-run", "--no-default-browser-check",
                "--disable-background-networking", "--disable-component-update", "--disable-sync",
                "--disable-default-apps", "--disable-extensions", "--mute-audio",
                "--force-color-profile=srgb", "--font-render-hinting=none", "--hide-scrollbars",
                "about:blank"]
        self.proc = subprocess.Popen(args, preexec_fn=child_fds, stdin=subprocess.DEVNULL,
                                     stdout=subprocess.DEVNULL, stderr=self._log, close_fds=False)
        os.close(to_browser_r)
        os.close(from_browser_w)
        self._buf = b""
        self._id = 0
        self.events = []

    def close(self):
        try:
            self.send("Browser.close")
        except Exception:
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        for fd in (self._r, self._w):
            try:
                os.close(fd)
            except OSError:
                pass
        shutil.rmtree(self.profile, ignore_errors=True)

    def _read_message(self, deadline):
        while b"\0" not in self._buf:
            if time.time() > deadline:
                raise TimeoutError("the browser did not answer in time")
            chunk = os.read(self._r, 1 << 20)
            if not chunk:
                raise RuntimeError("the browser closed its pipe")
            self._buf += chunk
        msg, self._buf = self._buf.split(b"\0", 1)
        return json.loads(msg)

    def send(self, method, params=None, session=None):
        self._id += 1
        req = {"id": self._id, "method": method, "params": params or {}}
        if session:
            req["sessionId"] = session
        os.write(self._w, json.dumps(req).encode() + b"\0")
        deadline = time.time() + self.timeout
        while True:
            msg = self._read_message(deadline)
            if msg.get("id") == self._id:
                if "error" in msg:
                    raise RuntimeError("%s: %s" % (method, msg["error"]))
                return msg.get("result", {})
            self.events.append(msg)

    def wait_event(self, method, session=None, timeout=None):
        deadline = time.time() + (timeout or self.timeout)
        for i, ev in enumerate(self.events):
            if ev.get("method") == method and (session is None or ev.get("sessionId") == session):
                return self.events.pop(i)
        while True:
            msg = self._read_message(deadline)
            if "id" in msg:
                continue
            if msg.get("method") == method and (session is None or msg.get("sessionId") == session):
                return msg
            self.events.append(msg)

    def page(self, width=1280, height=900, scale=1, dark=False):
        target = self.send("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = self.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        return Page(self, session, target, width, height, scale, dark)


class Page:
    def __init__(self, browser, session, target, width, height, scale, dark):
        self.b, self.s, self.target = browser, session, target
        for domain in ("Page", "Runtime", "Network", "Log"):
            self.cmd(domain + ".enable")
        self.cmd("Emulation.setDeviceMetricsOverride",
                 {"width": width, "height": height, "deviceScaleFactor": scale, "mobile": False})
        self.cmd("Emulation.setEmulatedMedia",
                 {"features": [{"name": "prefers-color-scheme", "value": "dark" if dark else "light"}]})

    def cmd(self, method, params=None):
        return self.b.send(method, params, self.s)

    def goto(self, url):
        self.cmd("Page.navigate", {"url": url})
        self.b.wait_event("Page.loadEventFired", self.s)

    def eval(self, expr):
        r = self.cmd("Runtime.evaluate", {"expression": expr, "returnByValue": True, "awaitPromise": True})
        if "exceptionDetails" in r:
            raise RuntimeError("script failed: %s\n%s" % (expr, r["exceptionDetails"]))
        return r["result"].get("value")

    def mouse(self, x, y):
        self.cmd("Input.dispatchMouseEvent", {"type": "mouseMoved", "x": x, "y": y})

    def key(self, key, code, keycode):
        for t in ("rawKeyDown", "keyUp"):
            self.cmd("Input.dispatchKeyEvent", {"type": t, "key": key, "code": code,
                                                "windowsVirtualKeyCode": keycode})

    def screenshot(self, clip=None):
        params = {"format": "png", "captureBeyondViewport": True}
        if clip:
            params["clip"] = dict(clip, scale=1)
        return base64.b64decode(self.cmd("Page.captureScreenshot", params)["data"])

    def events(self):
        """The session's events so far (console, network, log), drained."""
        mine = [e for e in self.b.events if e.get("sessionId") == self.s]
        self.b.events = [e for e in self.b.events if e.get("sessionId") != self.s]
        return mine

    def close(self):
        self.b.send("Target.closeTarget", {"targetId": self.target})
