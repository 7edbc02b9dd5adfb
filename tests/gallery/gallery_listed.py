#!/usr/bin/env python3
"""docs/gallery.md against the scenes (issue 24, item 3): every scene of options/*.opts and
every example of examples/*/ has an entry in the gallery, naming its scene file, its picture
and the command that runs it, and a row in the table of scripts/make_gallery (which makes the
picture); every picture the page shows exists in docs/ and is a PNG; no entry names a scene
that is gone. Fails with the list of what is missing.
"""
import glob
import os
import re
import sys

SOURCE = os.environ.get("POROSEAM_SOURCE",
                        os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
DOCS = os.path.join(SOURCE, "docs")
PAGE = os.path.join(DOCS, "gallery.md")


def main():
    problems = []
    if not os.path.isfile(PAGE):
        print(f"FAIL: {PAGE} does not exist")
        return 1
    text = open(PAGE).read()
    scenes = sorted(os.path.relpath(p, SOURCE) for p in glob.glob(os.path.join(SOURCE, "options", "*.opts")))
    scenes += sorted(os.path.relpath(os.path.join(d, os.path.basename(d) + ".opts"), SOURCE)
                     for d in glob.glob(os.path.join(SOURCE, "examples", "*")) if os.path.isdir(d))
    # One entry per scene: a heading "### <name>", the scene file, a picture gallery/<name>.png
    # and a command that runs the scene file.
    entries = {m.group(1): m.start() for m in re.finditer(r"^### +`?([A-Za-z0-9_]+)`?\s*$", text, re.M)}
    starts = sorted(entries.values()) + [len(text)]
    for scene in scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        if name not in entries:
            problems.append(f"{scene}: no entry '### {name}' in docs/gallery.md")
            continue
        start = entries[name]
        body = text[start:starts[starts.index(start) + 1]]
        if scene not in body:
            problems.append(f"{scene}: its entry does not name the scene file")
        if f"(gallery/{name}.png)" not in body:
            problems.append(f"{scene}: its entry shows no picture gallery/{name}.png")
        if not re.search(r"(scripts/run|poroseam)\b[^\n]*" + re.escape(os.path.basename(scene)[:-5]), body):
            problems.append(f"{scene}: its entry has no command that runs it")
    with open(os.path.join(SOURCE, "scripts", "make_gallery")) as f:
        rows = dict(re.findall(r'^\s*"([A-Za-z0-9_]+)\|([^|]+)\|', f.read(), re.M))
    for scene in scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        if rows.get(name) != scene:
            problems.append(f"{scene}: no row '{name}|{scene}|...' in the table of scripts/make_gallery")
    known = {os.path.splitext(os.path.basename(s))[0] for s in scenes}
    for name in entries:
        if name not in known:
            problems.append(f"docs/gallery.md: entry '{name}' has no scene options/{name}.opts or examples/{name}/")
    pictures = re.findall(r"!\[[^\]]*\]\(([^)]+)\)", text)
    for pic in pictures:
        path = os.path.join(DOCS, pic)
        if not os.path.isfile(path):
            problems.append(f"docs/gallery.md shows {pic}, which does not exist")
        elif open(path, "rb").read(8) != b"\x89PNG\r\n\x1a\n":
            problems.append(f"docs/gallery.md shows {pic}, which is not a PNG")
    print(f"{len(scenes)} scenes, {len(entries)} gallery entries, {len(pictures)} pictures")
    for p in problems:
        print("FAIL: " + p)
    if problems:
        return 1
    print("PASS: every scene has its entry, picture and command; every picture exists")
    return 0


if __name__ == "__main__":
    sys.exit(main())
