#!/usr/bin/env bash
# Fills the generated blocks of README.md and docs/*.md: the config key table (from `dynvo-cli
# config-keys --markdown`) and the results tables (from bench/results/*.md, written by the
# benchmark scripts).
# Runs no benchmark itself.
#   bash bench/update_readme.sh     (env: DYNVO_BUILD_DIR)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DYNVO_BUILD_DIR:-$root/build}"
cmake --build "$build" --target dynvo-cli >/dev/null
keys="$(mktemp)"
trap 'rm -f "$keys"' EXIT
"$build/bin/dynvo-cli" config-keys --markdown > "$keys"

python3 - "$keys" "$root" "$root/README.md" "$root"/docs/*.md <<'PY'
import re, sys
keys_path, root, pages = sys.argv[1], sys.argv[2], sys.argv[3:]
def fill(match):
    source = match.group(1)
    if source == "dynvo-cli config-keys --markdown":
        body = open(keys_path).read()
    else:
        try:
            body = open(root + "/" + source).read()
        except FileNotFoundError:
            body = "(not generated yet: run the script named above)\n"
    return "<!-- BEGIN generated: %s -->\n%s<!-- END generated -->" % (source, body)
for page in pages:
    text = open(page).read()
    new = re.sub(r"<!-- BEGIN generated: (.*?) -->\n.*?<!-- END generated -->", fill, text, flags=re.S)
    open(page, "w").write(new)
PY
echo "update_readme: generated blocks of README.md and docs/*.md refreshed"
