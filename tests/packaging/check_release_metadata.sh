#!/usr/bin/env bash
# The version lives in CMakeLists.txt (project VERSION); CITATION.cff and CHANGELOG.md repeat it by hand. This
# fails when they disagree, so a version bump cannot forget one of them.
# Usage: check_release_metadata.sh SOURCE_DIR VERSION
set -euo pipefail
source_dir=$1
version=$2
grep -qx "version: $version" "$source_dir/CITATION.cff" \
  || { echo "CITATION.cff: no line 'version: $version'" >&2; exit 1; }
grep -q "^## \[$version\] - [0-9]\{4\}-[0-9][0-9]-[0-9][0-9]$" "$source_dir/CHANGELOG.md" \
  || { echo "CHANGELOG.md: no section '## [$version] - YYYY-MM-DD'" >&2; exit 1; }
grep -q "^Copyright (c) .*the semslam developers" "$source_dir/LICENSE" \
  || { echo "LICENSE: no copyright line of the semslam developers" >&2; exit 1; }
