"""Write the Python code blocks of one README section, in order, as one script.

Usage: ``python .ci/readme_code.py README.md "<section title>" out.py``
(the section is the text from its ``## <section title>`` heading to the next ``## `` heading).
"""

import re
import sys


def main(readme: str, title: str, out: str) -> int:
    text = open(readme, encoding="utf-8").read()
    parts = text.split(f"\n## {title}\n", 1)
    if len(parts) != 2:
        print(f"{readme}: no section '## {title}'", file=sys.stderr)
        return 2
    section = parts[1].split("\n## ", 1)[0]
    blocks = re.findall(r"```python\n(.*?)```", section, re.S)
    if not blocks:
        print(f"{readme}: no python code block in '## {title}'", file=sys.stderr)
        return 2
    with open(out, "w", encoding="utf-8") as f:
        f.write("\n".join(blocks))
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
