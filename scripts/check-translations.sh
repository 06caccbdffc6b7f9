#!/bin/sh
# Every translation is complete: no entry marked unfinished or left empty, in every .ts file,
# and every source with translatable strings is one lupdate reads.
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
# Every source with translatable strings is in lupdate's list (app/editor/CMakeLists.txt):
# a file missing there keeps its strings in English and lupdate drops their translations.
for f in $(grep -rlE '\btr\(|QCoreApplication::translate\(' ui core/document --include='*.cpp'); do
  if ! grep -q "/$f" app/editor/CMakeLists.txt; then
    echo "$f has translatable strings but is not in app/editor/CMakeLists.txt's lupdate SOURCES"
    status=1
  fi
done
exit $status
