#!/usr/bin/env python3
"""Runs the ```bash blocks of the documentation, so that every documented command works as written.

  scripts/docs_commands.py [--root DIR] [--timeout SECONDS] [--jobs N] [--keep] [--list] [PAGE.md ...]

Pages: README.md, docs/tutorials/*.md and docs/how-to/*.md (or the PAGEs given). For each page:
- a fresh scratch directory with symlinks to the repository's scripts, config, launch, src, ppp_msgs,
  ppp_generator, ppp_agents, ppp_simulator and CMakeLists.txt, `build` pointing at the build directory
  ($PPP_BUILD_DIR, default REPO/build), and a copy of docs/ and README.md; a private tmp directory in it: every
  `/tmp/` (and a bare `/tmp`) in a block's text is replaced by it; HOME, ROS_HOME and TMPDIR in the scratch,
  ROS_MASTER_URI on a free loopback port, ROS_IP=127.0.0.1, /usr/bin first on PATH;
- its ```bash blocks run in order in one `bash -e -o pipefail` process started in the scratch (variables and the
  working directory carry from one block to the next), each preceded by an echo of its FILE:LINE; the page fails at
  the first failing command, naming its block, or after --timeout seconds (its process group is killed);
- a marker on the line(s) just before a block changes what runs:
      <!-- docs-test: instead
      COMMANDS
      -->                                       COMMANDS run in place of the block
      <!-- docs-test: skip (REASON) -->         the block is not run; REASON is printed in the summary
  a marker not followed by a ```bash block is an error. ```text, ```yaml, ```console ... blocks never run;
- afterwards, every file of the scratch's docs/ and README.md that the commands changed or made, and that the
  repository has too, must be byte-identical to the repository's (a committed picture is the output of its
  documented command); and the commands must not have changed the repository through the symlinks.

Prints one line per page (ok, or FAILED with the failing block's FILE:LINE and the tail of its output), then a
summary (blocks run, replaced, skipped with their reasons); exits 1 on any failure. --list prints the blocks it
would run and runs nothing. Standard library only.
"""
import argparse
import concurrent.futures
import hashlib
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time

LINKED = ["scripts", "config", "launch", "src", "ppp_msgs", "ppp_generator", "ppp_agents", "ppp_simulator",
          "CMakeLists.txt"]
COPIED = ["docs", "README.md"]
FENCE = re.compile(r"^(\s*)(`{3,}|~{3,})(.*)$")
MARKER = re.compile(r"^\s*<!--\s*docs-test\b(.*)$")
SKIP = re.compile(r"^\s*<!--\s*docs-test:\s*skip\s*\((.*\S.*)\)\s*-->\s*$")
INSTEAD = re.compile(r"^\s*<!--\s*docs-test:\s*instead\s*$")
TMP = re.compile(r"(?<![\w.~/$})\]-])/tmp(?=/|$|[\s\"';)|&<>`])")
TAIL_LINES = 30


class Block:
    """One ```bash block of a page and what runs for it."""

    def __init__(self, page, line, text, kind="run", marker_line=None, instead="", reason=""):
        self.page = page
        self.line = line  # of the opening fence
        self.text = text
        self.kind = kind  # run, instead or skip
        self.marker_line = marker_line
        self.instead = instead
        self.reason = reason

    @property
    def location(self):
        return "%s:%d" % (self.page, self.line)

    @property
    def commands(self):
        return self.instead if self.kind == "instead" else self.text


def dedent(lines, indent):
    """lines without up to `indent` leading spaces each (the indentation of a fence in a list item)."""
    result = []
    for line in lines:
        spaces = len(line) - len(line.lstrip(" "))
        result.append(line[min(spaces, indent):])
    return result


def common_dedent(lines):
    indents = [len(line) - len(line.lstrip(" ")) for line in lines if line.strip()]
    return dedent(lines, min(indents) if indents else 0)


def parse_page(root, page):
    """(blocks, errors) of a page: its ```bash blocks with their markers, and `FILE:LINE: message` errors."""
    with open(os.path.join(root, page), encoding="utf-8") as stream:
        lines = stream.read().split("\n")
    blocks, errors = [], []
    pending = None  # (kind, marker line, instead text, reason, the line the marker ends on)
    index = 0
    while index < len(lines):
        line = lines[index]
        number = index + 1
        fence = FENCE.match(line)
        if fence and not (fence.group(2)[0] == "`" and "`" in fence.group(3)):
            indent, marks, info = len(fence.group(1)), fence.group(2), fence.group(3).strip()
            language = info.split()[0].lower() if info else ""
            end = index + 1
            while end < len(lines):
                closing = FENCE.match(lines[end])
                if closing and closing.group(2)[0] == marks[0] and len(closing.group(2)) >= len(marks) \
                        and not closing.group(3).strip():
                    break
                end += 1
            if end == len(lines):
                errors.append("%s:%d: the code block is never closed (no %s line)" % (page, number, marks))
            content = dedent(lines[index + 1:end], indent)
            marker = pending if pending and pending[4] == index - 1 else None
            if pending and not marker:
                errors.append("%s:%d: docs-test marker not followed by a ```bash block (it must be on the line "
                              "just before the block)" % (page, pending[1]))
            pending = None
            if language == "bash":
                block = Block(page, number, "\n".join(content) + "\n")
                if marker:
                    block.kind, block.marker_line, block.instead, block.reason = marker[:4]
                for offset, text in enumerate(content):
                    if re.match(r"^\s*\$\s", text):
                        errors.append("%s:%d: a shell prompt in a ```bash block (commands only; put a session "
                                      "with its output in a ```console or ```text block)" % (page, number + 1 + offset))
                if content and content[-1].rstrip().endswith("\\"):
                    errors.append("%s:%d: the block ends with a line continuation" % (page, number + len(content)))
                blocks.append(block)
            elif marker:
                errors.append("%s:%d: docs-test marker not followed by a ```bash block (a ```%s block follows)"
                              % (page, marker[1], language or " block without a language"))
            if language in ("sh", "shell", "zsh"):
                errors.append("%s:%d: a ```%s block is neither run nor plain text: commands go in ```bash (run by "
                              "this test), output in ```text or ```console" % (page, number, language))
            index = end + 1
            continue
        if pending and pending[4] != index - 1:
            errors.append("%s:%d: docs-test marker not followed by a ```bash block (it must be on the line just "
                          "before the block)" % (page, pending[1]))
            pending = None
        if MARKER.match(line):
            if pending:
                errors.append("%s:%d: docs-test marker not followed by a ```bash block (another marker follows)"
                              % (page, pending[1]))
                pending = None
            skip = SKIP.match(line)
            if skip:
                pending = ("skip", number, "", skip.group(1).strip(), index)
            elif INSTEAD.match(line):
                end = index + 1
                while end < len(lines) and lines[end].strip() != "-->":
                    end += 1
                if end == len(lines):
                    errors.append("%s:%d: docs-test: instead marker never closed (no --> line)" % (page, number))
                    break
                commands = common_dedent(lines[index + 1:end])
                if not any(text.strip() for text in commands):
                    errors.append("%s:%d: docs-test: instead marker without commands (use docs-test: skip (reason))"
                                  % (page, number))
                else:
                    pending = ("instead", number, "\n".join(commands) + "\n", "", end)
                index = end + 1
                continue
            else:
                errors.append("%s:%d: unknown docs-test marker (expected `<!-- docs-test: skip (reason) -->` or "
                              "`<!-- docs-test: instead`, commands, `-->`)" % (page, number))
        index += 1
    if pending:
        errors.append("%s:%d: docs-test marker not followed by a ```bash block (the page ends)" % (page, pending[1]))
    return blocks, errors


def default_pages(root):
    pages = ["README.md"] if os.path.isfile(os.path.join(root, "README.md")) else []
    for folder in ("docs/tutorials", "docs/how-to"):
        directory = os.path.join(root, folder)
        if os.path.isdir(directory):
            pages += ["%s/%s" % (folder, name) for name in sorted(os.listdir(directory)) if name.endswith(".md")]
    return pages


def page_argument(root, argument):
    """A page given on the command line, as a path relative to root."""
    for candidate in (os.path.abspath(argument), os.path.join(root, argument)):
        if os.path.isfile(candidate):
            relative = os.path.relpath(os.path.realpath(candidate), root)
            if not relative.startswith(".."):
                return relative
    return None


def redirect_tmp(text, private):
    return TMP.sub(lambda match: private, text)


def free_port():
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def quoted(text):
    return "'" + text.replace("'", "'\\''") + "'"


def file_hash(path):
    digest = hashlib.sha256()
    with open(path, "rb") as stream:
        for chunk in iter(lambda: stream.read(1 << 20), b""):
            digest.update(chunk)
    return digest.hexdigest()


def copied_files(scratch):
    """Every regular file of the scratch's copies of docs/ and README.md, relative to the scratch."""
    found = []
    for name in COPIED:
        path = os.path.join(scratch, name)
        if os.path.isfile(path) and not os.path.islink(path):
            found.append(name)
        elif os.path.isdir(path) and not os.path.islink(path):
            for directory, subdirectories, names in os.walk(path):
                subdirectories.sort()
                for file in sorted(names):
                    full = os.path.join(directory, file)
                    if os.path.isfile(full) and not os.path.islink(full):
                        found.append(os.path.relpath(full, scratch))
    return found


class Runner:
    def __init__(self, root, build_dir, timeout, keep):
        self.root = root
        self.build_dir = build_dir
        self.timeout = timeout
        self.keep = keep
        self.work = tempfile.mkdtemp(prefix="ppp-docs-commands-")
        self.git = self._is_git_top_level()
        self.lock = threading.Lock()

    def _is_git_top_level(self):
        try:
            top = subprocess.run(["git", "-C", self.root, "rev-parse", "--show-toplevel"], capture_output=True,
                                 text=True, check=True).stdout.strip()
        except (OSError, subprocess.CalledProcessError):
            return False
        return os.path.realpath(top) == self.root

    def repository_state(self):
        """What git sees changed under the symlinked entries, with each such file's size and modification time:
        compared before and after a page to catch commands that write into the repository."""
        if not self.git:
            return {}
        entries = [name for name in LINKED if os.path.exists(os.path.join(self.root, name))]
        listed = subprocess.run(["git", "-C", self.root, "status", "--porcelain=v1", "-z", "--untracked-files=all",
                                 "--"] + entries, capture_output=True).stdout.decode("utf-8", "surrogateescape")
        state = {}
        for item in listed.split("\0"):
            if len(item) > 3:
                path = item[3:]
                try:
                    info = os.stat(os.path.join(self.root, path))
                    state[path] = (item[:2], info.st_size, info.st_mtime_ns)
                except OSError:
                    state[path] = (item[:2], None, None)
        return state

    def prepare(self, number, page):
        base = os.path.join(self.work, "%02d-%s" % (number, re.sub(r"[^A-Za-z0-9.-]+", "-", page)))
        scratch = os.path.join(base, "scratch")
        state = os.path.join(base, "state")
        os.makedirs(state)
        os.makedirs(scratch)
        for name in LINKED:
            if os.path.exists(os.path.join(self.root, name)):
                os.symlink(os.path.join(self.root, name), os.path.join(scratch, name))
        if os.path.isdir(self.build_dir):
            os.symlink(self.build_dir, os.path.join(scratch, "build"))
        for name in COPIED:
            source = os.path.join(self.root, name)
            if os.path.isdir(source):
                shutil.copytree(source, os.path.join(scratch, name), symlinks=True)
            elif os.path.isfile(source):
                shutil.copy2(source, os.path.join(scratch, name))
        for name in ("tmp", "home/.ros"):
            os.makedirs(os.path.join(scratch, name))
        return scratch, state

    def environment(self, scratch):
        environment = dict(os.environ)
        for name in ("ROS_HOSTNAME", "ROS_LOG_DIR", "ROS_NAMESPACE"):
            environment.pop(name, None)
        environment.update({
            "HOME": os.path.join(scratch, "home"),
            "ROS_HOME": os.path.join(scratch, "home", ".ros"),
            "TMPDIR": os.path.join(scratch, "tmp"),
            "ROS_MASTER_URI": "http://127.0.0.1:%d" % free_port(),
            "ROS_IP": "127.0.0.1",
            "PATH": "/usr/bin:/bin:" + os.environ.get("PATH", ""),
            "PPP_BUILD_DIR": self.build_dir,
        })
        return environment

    def script(self, blocks, scratch, state):
        """The page's bash script, and for each of its block lines the page's (block, line)."""
        private = os.path.join(scratch, "tmp")
        lines = [
            "# The commands of the page, generated by scripts/docs_commands.py.",
            "__docs_test_block() { printf '%%s\\n' \"$1\" >| %s/current; : >| %s/start-\"$2\"; "
            "printf '\\n=== docs-test: %%s\\n' \"$1\"; }" % (quoted(state), quoted(state)),
            # The command that stops the page (set -e): its script line, status and text.
            "trap '__docs_test_status=$?; printf \"%%s %%s\\n\" \"$LINENO\" \"$__docs_test_status\" >| %s/failed; "
            "printf \"=== docs-test: failed with status %%s: %%s\\n\" \"$__docs_test_status\" \"$BASH_COMMAND\"' ERR"
            % quoted(state).replace("'", "'\\''"),
            "cd %s" % quoted(scratch),
        ]
        where = {}
        for number, block in enumerate(blocks):
            if block.kind == "skip":
                continue
            label = block.location + (" (instead, marker at line %d)" % block.marker_line
                                      if block.kind == "instead" else "")
            lines.append("__docs_test_block %s %d" % (quoted(label), number))
            first = block.marker_line + 1 if block.kind == "instead" else block.line + 1
            commands = redirect_tmp(block.commands, private).rstrip("\n").split("\n")
            for offset, command in enumerate(commands):
                where[len(lines) + 1] = (block, first + offset)
                lines.append(command)
        lines.append("printf 'done\\n' >| %s/current" % quoted(state))
        return "\n".join(lines) + "\n", where

    def run_page(self, number, page, blocks, errors):
        """(ok, report lines) of one page."""
        started = time.monotonic()
        runnable = [block for block in blocks if block.kind != "skip"]
        counts = "%s run (%d instead), %d skipped" % (
            plural(len(runnable), "block"), sum(block.kind == "instead" for block in blocks),
            sum(block.kind == "skip" for block in blocks))
        if errors:
            return False, ["%s: FAILED (not run: its docs-test markers are wrong)" % page] + \
                ["    " + error for error in errors]
        if not runnable:
            return True, ["%s: ok (nothing to run: %s)" % (page, counts)]
        scratch, state = self.prepare(number, page)
        script = os.path.join(state, "page.sh")
        text, where = self.script(blocks, scratch, state)
        with open(script, "w") as stream:
            stream.write(text)
        copies = {name: file_hash(os.path.join(scratch, name)) for name in copied_files(scratch)}
        before = self.repository_state()
        log = os.path.join(state, "output.log")
        timed_out = False
        with open(log, "wb") as output:
            process = subprocess.Popen(["/bin/bash", "-e", "-o", "pipefail", script], cwd=scratch,
                                       env=self.environment(scratch), stdin=subprocess.DEVNULL, stdout=output,
                                       stderr=subprocess.STDOUT, start_new_session=True)
            try:
                status = process.wait(timeout=self.timeout)
            except subprocess.TimeoutExpired:
                timed_out = True
                kill_group(process.pid, signal.SIGTERM)
                try:
                    process.wait(timeout=5)
                except subprocess.TimeoutExpired:
                    pass
                status = None
            kill_group(process.pid, signal.SIGKILL)  # whatever the commands left running in the background
            process.wait()
        elapsed = time.monotonic() - started
        current = read(os.path.join(state, "current")).strip()
        problems = []
        if timed_out:
            problems.append("timed out after %d s in %s (the page's processes were killed)" % (self.timeout, current))
        elif status != 0:
            failed = read(os.path.join(state, "failed")).split()
            line = int(failed[0]) if failed and failed[0].isdigit() else None
            if line in where:
                block, page_line = where[line]
                problems.append("exit status %d at %s:%d (the block at %s)" % (status, page, page_line, current))
            else:
                problems.append("exit status %d at %s" % (status, current or page))
        elif current != "done":
            problems.append("the commands stopped early (an exit?) at %s" % (current or page))
        problems += self.pictures(page, blocks, scratch, state, copies)
        problems += self.repository_changes(page, before)
        if not problems:
            if not self.keep:
                shutil.rmtree(os.path.dirname(scratch), ignore_errors=True)
            return True, ["%s: ok (%s) in %.1f s" % (page, counts, elapsed)]
        report = ["%s: FAILED: %s" % (page, problems[0])] + ["    " + problem for problem in problems[1:]]
        if timed_out or status != 0 or current != "done":
            tail = read(log).rstrip("\n").split("\n")[-TAIL_LINES:]
            report += ["    | " + line for line in tail]
        if self.keep:
            report.append("    (scratch kept: %s)" % scratch)
        return False, report

    def pictures(self, page, blocks, scratch, state, copies):
        """Problems: files of the docs/ and README.md copies that the commands changed or made and that differ from
        the repository's."""
        problems = []
        starts = []
        for number, block in enumerate(blocks):
            try:
                starts.append((os.stat(os.path.join(state, "start-%d" % number)).st_mtime_ns, block))
            except OSError:
                pass
        starts.sort(key=lambda item: item[0])
        for name in copied_files(scratch):
            path = os.path.join(scratch, name)
            if copies.get(name) == file_hash(path):
                continue
            original = os.path.join(self.root, name)
            if not os.path.isfile(original) or file_hash(original) == file_hash(path):
                continue
            modified = os.stat(path).st_mtime_ns
            makers = [block for start, block in starts if start <= modified]
            where = ("the command in %s" % makers[-1].location) if makers else ("the commands of %s" % page)
            problems.append("%s: %s makes a different file" % (name, where))
        return problems

    def repository_changes(self, page, before):
        after = self.repository_state()
        changed = sorted(path for path in set(before) | set(after) if before.get(path) != after.get(path))
        return ["%s: changed in the repository while %s ran (its commands must write under the scratch or /tmp/)"
                % (path, page) for path in changed]

    def close(self):
        if self.keep:
            print("docs_commands: scratch directories kept under %s" % self.work)
        else:
            shutil.rmtree(self.work, ignore_errors=True)


def plural(count, noun):
    return "%d %s%s" % (count, noun, "" if count == 1 else "s")


def kill_group(pid, sig):
    try:
        os.killpg(pid, sig)
    except (ProcessLookupError, PermissionError):
        pass


def read(path):
    try:
        with open(path, encoding="utf-8", errors="replace") as stream:
            return stream.read()
    except OSError:
        return ""


def list_blocks(pages, parsed):
    for page in pages:
        blocks, errors = parsed[page]
        print("%s: %s" % (page, plural(len(blocks), "bash block")))
        for block in blocks:
            if block.kind == "skip":
                print("  %s: skip (%s)" % (block.location, block.reason))
                continue
            if block.kind == "instead":
                print("  %s: instead (marker at line %d) of:" % (block.location, block.marker_line))
                print("".join("      # " + line + "\n" for line in block.text.rstrip("\n").split("\n")), end="")
                print("    runs:")
            else:
                print("  %s: run" % block.location)
            print("".join("      " + line + "\n" for line in block.commands.rstrip("\n").split("\n")), end="")
        for error in errors:
            print("  ERROR " + error)


def main():
    default_root = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("pages", nargs="*", metavar="PAGE.md",
                        help="pages to run (default: README.md, docs/tutorials/*.md, docs/how-to/*.md)")
    parser.add_argument("--root", default=default_root,
                        help="the repository (default: the one holding this script, %(default)s)")
    parser.add_argument("--timeout", type=float, default=300, help="seconds per page (default: %(default)s)")
    parser.add_argument("--jobs", "-j", type=int, default=1, help="pages run at once (default: %(default)s)")
    parser.add_argument("--keep", action="store_true", help="keep the scratch directories")
    parser.add_argument("--list", action="store_true", help="print the blocks that would run; run nothing")
    options = parser.parse_args()
    root = os.path.realpath(options.root)
    if not os.path.isdir(root):
        parser.error("--root: no such directory: %s" % options.root)
    if options.timeout <= 0:
        parser.error("--timeout: expected a positive number of seconds, got %g" % options.timeout)
    if options.jobs < 1:
        parser.error("--jobs: expected at least 1, got %d" % options.jobs)
    if options.pages:
        pages = []
        for argument in options.pages:
            page = page_argument(root, argument)
            if page is None:
                parser.error("no such page in %s: %s" % (root, argument))
            pages.append(page)
    else:
        pages = default_pages(root)
    parsed = {page: parse_page(root, page) for page in pages}
    if options.list:
        list_blocks(pages, parsed)
        return 1 if any(errors for _, errors in parsed.values()) else 0

    build_dir = os.path.realpath(os.environ.get("PPP_BUILD_DIR") or os.path.join(root, "build"))
    runner = Runner(root, build_dir, options.timeout, options.keep)
    results = {}

    def run(item):
        number, page = item
        ok, report = runner.run_page(number, page, *parsed[page])
        with runner.lock:
            print("\n".join(report), flush=True)
        results[page] = ok

    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=options.jobs) as pool:
            list(pool.map(run, enumerate(pages)))
    finally:
        runner.close()

    blocks = [block for page in pages for block in parsed[page][0]]
    skipped = [block for block in blocks if block.kind == "skip"]
    failed = [page for page in pages if not results.get(page)]
    print("docs_commands: %s, %s: %d run (%d of them replaced by instead markers), %d skipped%s"
          % (plural(len(pages), "page"), plural(len(blocks), "bash block"), len(blocks) - len(skipped),
             sum(block.kind == "instead" for block in blocks), len(skipped), ":" if skipped else ""))
    for block in skipped:
        print("  %s: skipped (%s)" % (block.location, block.reason))
    if failed:
        print("docs_commands: FAILED: %s" % ", ".join(failed))
        return 1
    print("docs_commands: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
