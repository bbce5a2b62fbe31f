#!/usr/bin/python3
"""Writes the ```cpp blocks of a markdown file into OUT_DIR/doc_example.cpp and each ```glsl block
(first line "// file: NAME") into OUT_DIR/NAME, so documentation code is compiled and tested.
Prints the GLSL file paths, one per line. Files are rewritten only when their content changed."""
import pathlib
import re
import sys


def write_if_changed(path: pathlib.Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    if not path.exists() or path.read_text() != text:
        path.write_text(text)


def main() -> int:
    markdown, out_dir = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    blocks = re.findall(r"^```(cpp|glsl)\n(.*?)^```", markdown.read_text(), re.S | re.M)
    cpp = [f"// Extracted from {markdown.name}. Do not edit.\n"]
    for kind, body in blocks:
        if kind == "cpp":
            cpp.append(body)
            continue
        first, _, rest = body.partition("\n")
        match = re.fullmatch(r"// file: (\S+)", first.strip())
        if not match:
            print(f"{markdown}: a glsl block lacks its '// file: NAME' first line", file=sys.stderr)
            return 1
        target = out_dir / match.group(1)
        write_if_changed(target, rest)
        print(target)
    write_if_changed(out_dir / "doc_example.cpp", "".join(cpp))
    return 0


if __name__ == "__main__":
    sys.exit(main())
