#!/bin/sh
# Every translation is complete: no entry marked unfinished or left empty, in every .ts file.
# (The .ts files are refreshed from the sources with the update_translations target.)
set -eu
cd "$(dirname "$0")/.."
status=0
for ts in translations/*.ts; do
  unfinished=$(grep -c 'type="unfinished"' "$ts" || true)
  empty=$(grep -c '<translation></translation>\|<translation/>' "$ts" || true)
  messages=$(grep -c '<message' "$ts" || true)
  echo "$ts: $messages messages, $unfinished unfinished, $empty empty"
  [ "$unfinished" -eq 0 ] && [ "$empty" -eq 0 ] && [ "$messages" -gt 0 ] || status=1
done
exit $status
