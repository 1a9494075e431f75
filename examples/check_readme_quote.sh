#!/usr/bin/env bash
# Usage: check_readme_quote.sh EXAMPLE.cpp README.md
# Fails unless README.md's block between "<!-- library_example: begin -->" and
# "<!-- library_example: end -->" holds, inside its code fence, exactly the example's lines between
# "// [readme-begin]" and "// [readme-end]" (indentation removed). Keeps the quote true.
set -euo pipefail
example=$1 readme=$2
strip() { sed -e 's/^[[:space:]]*//' -e 's/[[:space:]]*$//'; }
code=$(sed -n '/\/\/ \[readme-begin\]/,/\/\/ \[readme-end\]/p' "$example" | sed '1d;$d' | strip)
quote=$(sed -n '/<!-- library_example: begin -->/,/<!-- library_example: end -->/p' "$readme" |
        sed -n '/^```cpp$/,/^```$/p' | sed '1d;$d' | grep -v '^#include' | strip | sed '/^$/d')
if [[ -z $code ]]; then echo "no [readme-begin]/[readme-end] block in $example"; exit 1; fi
if [[ $code != "$quote" ]]; then
  echo "README.md does not quote $example as it is:"
  diff <(echo "$code") <(echo "$quote") || true
  exit 1
fi
echo "README.md quotes the example's $(echo "$code" | wc -l) lines"
