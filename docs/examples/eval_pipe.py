#!/usr/bin/env python3
"""amorph from Python's standard library alone (docs/embedding.md).

Two ways to evaluate robots:
  * ctypes: load build/libamorph.so (make shared) and call the embedding API (amorph/api.h) on a
    workspace this program allocates;
  * a pipe: start `amorph eval` once and send it batches of JSON lines, reading one JSON result per
    robot and an empty line after each batch (ask/tell).

Usage: eval_pipe.py [--lib LIB] [--amorph AMORPH] [--set KEY=VALUE ...] ROBOT...
(defaults: $AMORPH_LIB, else the checkout's build/libamorph.so, and build/amorph, found from this
file's place, so it runs from any folder; tools/python/amorph.py is the module for programs)
Each ROBOT is a genome or lattice file. For every robot it prints one line: the file, then
"ctypes" and "pipe" each with fitness (as %.9g, what amorph sim prints) and hash (16 hex digits).
"""
import argparse
import ctypes
import json
import os
import subprocess
import sys


# am_result's mirror, field by field: the module's (tools/python/amorph.py)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "python"))
from amorph import Result  # noqa: E402


class Amorph:
    """one workspace of libamorph.so: settings, then evaluations (one thread at a time per object)"""

    def __init__(self, path, settings=()):
        lib = ctypes.CDLL(path)
        lib.am_api_work_size.restype = ctypes.c_long
        lib.am_api_result_size.restype = ctypes.c_long
        for name in ("am_api_init", "am_api_set", "am_api_eval_genome", "am_api_eval_lattice"):
            getattr(lib, name).restype = ctypes.c_int
        if lib.am_api_result_size() != ctypes.sizeof(Result):
            raise RuntimeError("am_result is %d bytes in %s, %d here" % (lib.am_api_result_size(), path, ctypes.sizeof(Result)))
        self.lib = lib
        size = lib.am_api_work_size()
        self.work = ctypes.create_string_buffer(size)  # malloc'd: aligned for a double
        self.err = ctypes.create_string_buffer(512)
        self._check(lib.am_api_init(self.work, ctypes.c_long(size), self.err, len(self.err)))
        for key, value in settings:
            self.set(key, value)

    def _check(self, status):
        if status != 0:
            raise ValueError(self.err.value.decode())

    def set(self, key, value):
        self._check(self.lib.am_api_set(self.work, key.encode(), str(value).encode(), self.err, len(self.err)))

    def evaluate(self, text):
        """a genome or a lattice text: its am_result"""
        r = Result()
        fn = self.lib.am_api_eval_genome if text.startswith("amorph-genome") else self.lib.am_api_eval_lattice
        self._check(fn(self.work, text.encode(), ctypes.byref(r), self.err, len(self.err)))
        return r


class Pipe:
    """`amorph eval` as a child process: ask with a batch, tell the results"""

    def __init__(self, amorph, settings=(), threads=0):
        args = [amorph, "eval", "--threads", str(threads)]
        for key, value in settings:
            args += ["--" + key, str(value)]
        self.proc = subprocess.Popen(args, stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)

    def evaluate(self, texts):
        """a batch of genome or lattice texts: their results (dicts), in order"""
        for i, text in enumerate(texts):
            kind = "genome" if text.startswith("amorph-genome") else "lattice"
            self.proc.stdin.write(json.dumps({"id": i, kind: text}) + "\n")
        self.proc.stdin.write("\n")  # the batch ends
        self.proc.stdin.flush()
        results = []
        while True:
            line = self.proc.stdout.readline()
            if not line:
                raise RuntimeError("amorph eval ended (exit status %s)" % self.proc.wait())
            if line == "\n":
                return results
            results.append(json.loads(line))

    def close(self):
        self.proc.stdin.close()
        return self.proc.wait()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    # defaults: the checkout's build/, found from this file's place (the example runs from any folder)
    build = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "build")
    ap.add_argument("--lib", default=os.environ.get("AMORPH_LIB") or os.path.join(build, "libamorph.so"))
    ap.add_argument("--amorph", default=os.path.join(build, "amorph"))
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE")
    ap.add_argument("robots", nargs="+")
    a = ap.parse_args()
    settings = [s.split("=", 1) for s in a.set]
    texts = [open(p).read() for p in a.robots]
    am = Amorph(a.lib, settings)
    pipe = Pipe(a.amorph, settings)
    piped = pipe.evaluate(texts)
    if pipe.close() != 0:
        return 1
    for path, text, p in zip(a.robots, texts, piped):
        r = am.evaluate(text)
        print("%s ctypes %.9g %016x pipe %.9g %s" % (path, r.fitness, r.hash, p["fitness"], p["hash"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
