#!/usr/bin/env python3
"""Checks the documentation's links and that no file cites a document outside the repository.

  scripts/docs_links.py [--root DIR]

1. In README.md, BENCHMARKS.md and every docs/**/*.md: every relative link and image (`[t](path)`,
   `[t](path#anchor)`, `[t](#anchor)`, `![a](img)`, a reference definition `[t]: path`, an HTML `href=` or
   `src=`) must name a file or directory of the repository (not one git ignores), and an anchor must name a
   heading of the target Markdown file as GitHub makes it (or an explicit `<a name=...>` / `id=...`). A
   `[text][label]` must have its `[label]: ...` definition. Links in fenced code blocks, inline code and HTML
   comments are not links. http(s), mailto and other URLs with a scheme are not fetched.
2. No text file tracked by git (nor any of the Markdown files above) cites a document that lives outside the
   repository: the whole word made of the letters S, P, E, C in capitals, a relative path to a "shared" folder
   beside the repository, or a "shared" docs folder.

Prints one line per problem, `FILE:LINE: what is wrong`, and exits 1 if there is any; otherwise prints a one-line
summary and exits 0. Standard library only.
"""
import argparse
import difflib
import html
import os
import re
import subprocess
import sys
import unicodedata
import urllib.parse

# Spelled in pieces so that this file does not cite them itself.
OUTSIDE_CITATIONS = [
    (re.compile(r"\bSP" r"EC\b"), "SP" "EC"),
    (re.compile(re.escape("../" "shared")), "../" "shared"),
    (re.compile(re.escape("shared" "/docs")), "shared" "/docs"),
]
NOT_SCANNED_SUFFIXES = (".ppp",)

FENCE = re.compile(r"^(\s*)(`{3,}|~{3,})(.*)$")
ATX_HEADING = re.compile(r"^ {0,3}(#{1,6})(?:[ \t]+(.*?))?[ \t]*$")
SETEXT_UNDERLINE = re.compile(r"^ {0,3}(=+|-+)[ \t]*$")
NOT_PARAGRAPH = re.compile(r"^\s*(?:[-*+]\s|\d+[.)]\s|>|\||#|<|$)")
REFERENCE_DEFINITION = re.compile(r"^ {0,3}\[((?:[^\]\\]|\\.)+)\]:[ \t]*(?:\n[ \t]*)?(<[^>\n]*>|\S+)"
                                  r"[ \t]*(?:(?:\"[^\"\n]*\"|'[^'\n]*'|\([^)\n]*\))[ \t]*)?$", re.M)
REFERENCE_USE = re.compile(r"(?<![\w\]\\])\[((?:[^\]\\\n]|\\.)*)\]\[((?:[^\]\\]|\\.)*)\](?![(:\[])")
HTML_LINK = re.compile(r"<(?:a|img|source|video|audio|link)\b[^>]*?\b(href|src)\s*=\s*([\"'])(.*?)\2", re.I | re.S)
HTML_ANCHOR = re.compile(r"<[a-zA-Z][^>]*?\b(?:name|id)\s*=\s*([\"'])(.*?)\1", re.S)
SCHEME = re.compile(r"^[a-zA-Z][a-zA-Z0-9+.-]*:")
LINE_ANCHOR = re.compile(r"^L(\d+)(?:-L(\d+))?$")


def markdown_files(root):
    """README.md, BENCHMARKS.md and docs/**/*.md under root, as paths relative to it."""
    files = [name for name in ("README.md", "BENCHMARKS.md") if os.path.isfile(os.path.join(root, name))]
    docs = os.path.join(root, "docs")
    found = []
    for directory, subdirectories, names in os.walk(docs):
        subdirectories.sort()
        for name in names:
            if name.endswith(".md"):
                found.append(os.path.relpath(os.path.join(directory, name), root))
    return files + sorted(found)


def blank(text, start, end):
    """text with [start, end) replaced by spaces, newlines kept (so offsets and line numbers stay)."""
    return text[:start] + re.sub(r"[^\n]", " ", text[start:end]) + text[end:]


def code_spans(text):
    """(start, end, content) of every inline code span of text (CommonMark backtick-string matching)."""
    spans = []
    position = 0
    while True:
        opening = re.compile(r"(?<![`\\])`+").search(text, position)
        if not opening:
            return spans
        ticks = opening.group(0)
        closing = re.compile(r"(?<!`)" + ticks + r"(?!`)").search(text, opening.end())
        if not closing:
            position = opening.end()
            continue
        content = text[opening.end():closing.start()].replace("\n", " ")
        if len(content) > 1 and content.startswith(" ") and content.endswith(" ") and content.strip():
            content = content[1:-1]
        spans.append((opening.start(), closing.end(), content))
        position = closing.end()


class Document:
    """A Markdown file: its lines with code and comments blanked out, its anchors, its links."""

    def __init__(self, path):
        with open(path, encoding="utf-8", errors="replace") as stream:
            self.raw = stream.read()
        lines = self.raw.split("\n")
        # Fenced code blocks: blank every line from the opening fence to the closing one.
        in_fence = None
        for index, line in enumerate(lines):
            match = FENCE.match(line)
            if in_fence:
                if match and match.group(2)[0] == in_fence[0] and len(match.group(2)) >= len(in_fence) \
                        and not match.group(3).strip():
                    in_fence = None
                lines[index] = ""
            elif match and not (match.group(2)[0] == "`" and "`" in match.group(3)):
                in_fence = match.group(2)
                lines[index] = ""
        text = "\n".join(lines)
        # HTML comments (the docs-test markers among them) render as nothing.
        for comment in reversed(list(re.finditer(r"<!--.*?-->", text, re.S))):
            text = blank(text, comment.start(), comment.end())
        self.without_fences = text
        # Inline code, paragraph by paragraph (a code span may wrap onto the next line but not cross a blank line).
        parts = re.split(r"(\n[ \t]*\n)", text)
        cleaned = []
        for part in parts:
            for start, end, _ in reversed(code_spans(part)):
                part = blank(part, start, end)
            cleaned.append(part)
        self.text = "".join(cleaned)
        self.line_starts = [0] + [match.end() for match in re.finditer(r"\n", self.text)]
        self.anchors = self._anchors()

    def line_of(self, offset):
        low, high = 0, len(self.line_starts) - 1
        while low < high:
            middle = (low + high + 1) // 2
            if self.line_starts[middle] <= offset:
                low = middle
            else:
                high = middle - 1
        return low + 1

    def _anchors(self):
        """Every anchor GitHub gives this file: heading slugs (deduplicated as GitHub does) and explicit ids."""
        slugs = Slugger()
        anchors = set()
        lines = self.without_fences.split("\n")
        for index, line in enumerate(lines):
            match = ATX_HEADING.match(line)
            if match:
                content = re.sub(r"(?:^|[ \t]+)#+$", "", match.group(2) or "")
                anchors.add(slugs.slug(heading_text(content)))
                continue
            previous = lines[index - 1] if index > 0 else ""
            if SETEXT_UNDERLINE.match(line) and not NOT_PARAGRAPH.match(previous) and not FENCE.match(previous) \
                    and not SETEXT_UNDERLINE.match(previous):
                first = index - 1
                while first > 0 and lines[first - 1].strip() and not NOT_PARAGRAPH.match(lines[first - 1]):
                    first -= 1
                anchors.add(slugs.slug(heading_text(" ".join(l.strip() for l in lines[first:index]))))
        for match in HTML_ANCHOR.finditer(self.text):
            anchors.add(html.unescape(match.group(2)))
        return anchors

    def links(self):
        """(line, kind, destination) of every link, image and reference definition outside code."""
        found = []
        text = self.text
        for match in re.finditer(r"\]\(", text):
            opening = matching_bracket(text, match.start())
            if opening is None:
                continue
            destination = link_destination(text, match.end())
            if destination is None:
                continue
            kind = "image" if opening > 0 and text[opening - 1] == "!" else "link"
            found.append((self.line_of(match.start()), kind, destination))
        definitions = {}
        for match in REFERENCE_DEFINITION.finditer(text):
            destination = match.group(2)
            if destination.startswith("<"):
                destination = destination[1:-1]
            definitions[normal_label(match.group(1))] = destination
            found.append((self.line_of(match.start(1)), "link", destination))
        for match in REFERENCE_USE.finditer(text):
            label = match.group(2) or match.group(1)
            if normal_label(label) not in definitions:
                found.append((self.line_of(match.start()), "reference", label))
        for match in HTML_LINK.finditer(text):
            kind = "image" if match.group(1).lower() == "src" else "link"
            found.append((self.line_of(match.start(3)), kind, html.unescape(match.group(3))))
        found.sort(key=lambda item: item[0])
        return found


def normal_label(label):
    return re.sub(r"\s+", " ", label.strip()).casefold()


def matching_bracket(text, close):
    """The offset of the `[` that the `]` at close ends, or None."""
    depth = 0
    index = close
    while index >= 0:
        character = text[index]
        escaped = index > 0 and text[index - 1] == "\\"
        if character == "]" and not escaped:
            depth += 1
        elif character == "[" and not escaped:
            depth -= 1
            if depth == 0:
                return index
        elif character == "\n" and index > 0 and text[index - 1] == "\n":
            return None
        index -= 1
    return None


def link_destination(text, start):
    """The destination of an inline link whose `(` ends just before start, or None if it is no link."""
    index = start
    while index < len(text) and text[index] in " \t":
        index += 1
    if index < len(text) and text[index] == "\n":
        index += 1
        while index < len(text) and text[index] in " \t":
            index += 1
    if index < len(text) and text[index] == "<":
        end = text.find(">", index)
        if end < 0 or "\n" in text[index:end]:
            return None
        destination = text[index + 1:end]
        index = end + 1
    else:
        depth = 0
        begin = index
        while index < len(text):
            character = text[index]
            if character == "\\" and index + 1 < len(text):
                index += 2
                continue
            if character.isspace():
                break
            if character == "(":
                depth += 1
            elif character == ")":
                if depth == 0:
                    break
                depth -= 1
            index += 1
        destination = text[begin:index]
    # The rest: an optional title, then `)`.
    rest = re.match(r"\s*(?:\"[^\"]*\"|'[^']*'|\([^)]*\))?\s*\)", text[index:])
    if not rest:
        return None
    return re.sub(r"\\([!-/:-@\[-`{-~])", r"\1", destination)


class Slugger:
    """GitHub's heading anchors (github-slugger): lowercase, punctuation dropped, spaces to `-`, repeats numbered."""

    def __init__(self):
        self.occurrences = {}

    def slug(self, text):
        base = "".join(character for character in text.lower() if character in " -_"
                       or unicodedata.category(character)[0] in "LMN" or unicodedata.category(character) == "Pc")
        base = base.replace(" ", "-")
        result = base
        while result in self.occurrences:
            self.occurrences[base] += 1
            result = "%s-%d" % (base, self.occurrences[base])
        self.occurrences[result] = 0
        return result


def heading_text(content):
    """The text GitHub renders for a heading's Markdown: code kept without backticks, links as their text,
    images, tags and emphasis markers dropped."""
    protected = []

    def protect(match_content):
        protected.append(match_content)
        return "\0%d\0" % (len(protected) - 1)

    pieces = []
    position = 0
    for start, end, code in code_spans(content):
        pieces.append(content[position:start])
        pieces.append(protect(code))
        position = end
    pieces.append(content[position:])
    text = "".join(pieces)
    text = re.sub(r"!\[[^\]]*\]\([^)]*\)", "", text)
    text = re.sub(r"!\[[^\]]*\]\[[^\]]*\]", "", text)
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)
    text = re.sub(r"\[([^\]]*)\]\[[^\]]*\]", r"\1", text)
    text = re.sub(r"<[^>\0]*>", "", text)
    text = re.sub(r"(?<![0-9A-Za-z])_+|_+(?![0-9A-Za-z])", "", text)
    text = re.sub(r"\\([!-/:-@\[-`{-~])", r"\1", text)
    text = html.unescape(text)
    text = re.sub(r"\0(\d+)\0", lambda match: protected[int(match.group(1))], text)
    return text.strip()


class Checker:
    def __init__(self, root):
        self.root = os.path.realpath(root)
        self.problems = []
        self.documents = {}
        self.links_checked = 0
        self.external = 0
        self.git = self._is_git_top_level()
        self.ignored_cache = {}

    def problem(self, file, line, message):
        self.problems.append((file, line, message))

    def _is_git_top_level(self):
        try:
            top = subprocess.run(["git", "-C", self.root, "rev-parse", "--show-toplevel"], capture_output=True,
                                 text=True, check=True).stdout.strip()
        except (OSError, subprocess.CalledProcessError):
            return False
        return os.path.realpath(top) == self.root

    def document(self, relative):
        if relative not in self.documents:
            self.documents[relative] = Document(os.path.join(self.root, relative))
        return self.documents[relative]

    def ignored(self, relative):
        if not self.git:
            return False
        if relative not in self.ignored_cache:
            result = subprocess.run(["git", "-C", self.root, "check-ignore", "-q", "--", relative],
                                    capture_output=True)
            self.ignored_cache[relative] = result.returncode == 0
        return self.ignored_cache[relative]

    def check_links(self, relative):
        document = self.document(relative)
        for line, kind, destination in document.links():
            if kind == "reference":
                self.problem(relative, line, "reference [%s] is not defined" % destination)
                continue
            self.check_link(relative, line, kind, destination)

    def check_link(self, relative, line, kind, destination):
        if SCHEME.match(destination) or destination.startswith("//"):
            self.external += 1
            return
        self.links_checked += 1
        if not destination:
            self.problem(relative, line, "%s with an empty destination" % kind)
            return
        path, _, anchor = destination.partition("#")
        path = urllib.parse.unquote(path.partition("?")[0])
        anchor = urllib.parse.unquote(anchor)
        shown = ("link to %s" if kind == "link" else "image %s") % destination
        if path.startswith("/"):
            self.problem(relative, line, "%s: an absolute path (use a path relative to %s)" % (shown, relative))
            return
        if path:
            target = os.path.normpath(os.path.join(os.path.dirname(relative), path))
            if target == ".." or target.startswith("../") or os.path.isabs(target):
                self.problem(relative, line, "%s: outside the repository" % shown)
                return
            full = os.path.join(self.root, target)
            if not os.path.exists(full):
                self.problem(relative, line, "%s: no such file" % shown)
                return
            if target != "." and self.ignored(target):
                self.problem(relative, line, "%s: ignored by git (not in the repository)" % shown)
                return
        else:
            target = relative
            full = os.path.join(self.root, target)
        if not anchor:
            return
        if os.path.isdir(full):
            readme = os.path.join(target, "README.md")
            if os.path.isfile(os.path.join(self.root, readme)):
                target, full = readme, os.path.join(self.root, readme)
            else:
                self.problem(relative, line, "anchor #%s on directory %s" % (anchor, target))
                return
        if not target.endswith(".md"):
            numbers = LINE_ANCHOR.match(anchor)
            if numbers:
                with open(full, "rb") as stream:
                    count = stream.read().count(b"\n") + 1
                if max(int(number) for number in numbers.groups() if number) > count:
                    self.problem(relative, line, "anchor #%s past the end of %s (%d lines)" % (anchor, target, count))
            else:
                self.problem(relative, line, "anchor #%s on %s, which is not Markdown" % (anchor, target))
            return
        anchors = self.document(target).anchors
        if anchor in anchors:
            return
        message = "anchor #%s not found in %s" % (anchor, target)
        close = [name for name in anchors if name.lower() == anchor.lower()] or \
            difflib.get_close_matches(anchor, sorted(anchors), n=1, cutoff=0.75)
        if close:
            message += " (did you mean #%s?)" % close[0]
        self.problem(relative, line, message)

    def scanned_files(self, markdown):
        """The text files to scan for citations: git's tracked files (every file when root is no git repository),
        and the checked Markdown files (tracked or not yet)."""
        if self.git:
            listed = subprocess.run(["git", "-C", self.root, "ls-files", "-z"], capture_output=True,
                                    check=True).stdout.decode("utf-8", "surrogateescape").split("\0")
            files = [name for name in listed if name]
        else:
            files = []
            for directory, subdirectories, names in os.walk(self.root):
                subdirectories[:] = sorted(name for name in subdirectories if name != ".git")
                files.extend(os.path.relpath(os.path.join(directory, name), self.root) for name in names)
        return sorted(set(files) | set(markdown))

    def check_citations(self, relative):
        if relative.endswith(NOT_SCANNED_SUFFIXES):
            return False
        full = os.path.join(self.root, relative)
        if not os.path.isfile(full) or os.path.islink(full):
            return False
        with open(full, "rb") as stream:
            data = stream.read()
        if b"\0" in data[:8192]:
            return False
        try:
            text = data.decode("utf-8")
        except UnicodeDecodeError:
            return False
        for number, line in enumerate(text.split("\n"), 1):
            for pattern, shown in OUTSIDE_CITATIONS:
                if pattern.search(line):
                    self.problem(relative, number, "cites a document outside the repository (\"%s\")" % shown)
        return True

    def run(self):
        markdown = markdown_files(self.root)
        for relative in markdown:
            self.check_links(relative)
        scanned = sum(1 for relative in self.scanned_files(markdown) if self.check_citations(relative))
        return markdown, scanned


def main():
    default_root = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--root", default=default_root,
                        help="the repository to check (default: the one holding this script, %(default)s)")
    options = parser.parse_args()
    if not os.path.isdir(options.root):
        parser.error("--root: no such directory: %s" % options.root)
    checker = Checker(options.root)
    markdown, scanned = checker.run()
    for file, line, message in sorted(checker.problems, key=lambda item: (item[0], item[1])):
        print("%s:%d: %s" % (file, line, message))
    if checker.problems:
        print("docs_links: %d problems (%d Markdown files, %d relative links checked, %d text files scanned)"
              % (len(checker.problems), len(markdown), checker.links_checked, scanned), file=sys.stderr)
        return 1
    print("docs_links: ok: %d Markdown files, %d relative links checked (%d external not fetched), "
          "%d text files scanned for outside citations" % (len(markdown), checker.links_checked, checker.external,
                                                            scanned))
    return 0


if __name__ == "__main__":
    sys.exit(main())
