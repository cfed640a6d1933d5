#!/usr/bin/env bash
# Checks that the user's pages still describe the tree (issue 46):
#   - README.md is at most 300 lines (a newcomer's page; history goes to
#     lab/records/);
#   - every relative link or image in README.md, docs/*.md and
#     lab/records/README.md points to a file or folder that exists;
#   - every repository path those pages name under mlndt/, tools/, lab/,
#     scripts/, tests/, examples/, benchmarks/ or python/ exists (a path
#     inside a longer one, such as build/tools/mlndt_align, is not one;
#     `*` globs and {a,b} alternatives are expanded).
# Prints one line per problem and exits 1 when there is one, 0 otherwise.
#   scripts/check_docs.sh
set -uo pipefail
cd "$(dirname "$0")/.." || exit 2

max_readme_lines=300
pages=(README.md docs/*.md lab/records/README.md)
problems=0

problem() {
  echo "check_docs: $*" >&2
  problems=$((problems + 1))
}

# True when PATTERN (relative to the repository root, with * globs and
# {a,b} alternatives) names at least one existing file or folder.
exists() {
  local pattern="$1" expanded
  # Brace expansion of the pattern itself, then globbing: eval on a string
  # made only of path characters (checked by the caller's regex).
  for expanded in $(eval "echo $pattern"); do
    compgen -G "$expanded" > /dev/null && return 0
    # An integration's header, named as it is included (mlndt/pcl/...).
    compgen -G "integrations/*/$expanded" > /dev/null && return 0
  done
  return 1
}

readme_lines=$(wc -l < README.md)
if ((readme_lines > max_readme_lines)); then
  problem "README.md has $readme_lines lines, more than $max_readme_lines (move history to lab/records/)"
fi

for page in "${pages[@]}"; do
  [[ -f $page ]] || continue
  dir=$(dirname "$page")
  # Relative links and images: ](target) with no scheme; the #anchor is
  # dropped (anchors are not checked).
  while IFS=: read -r line target; do
    target="${target%%#*}"
    [[ -z $target ]] && continue
    [[ -e "$dir/$target" ]] || problem "$page:$line: link to a missing file: $target"
  done < <(grep -noE '\]\([^)[:space:]]+\)' "$page" |
    sed -E 's/^([0-9]+):\]\((.*)\)$/\1:\2/' |
    grep -vE '^[0-9]+:([a-zA-Z][a-zA-Z0-9+.-]*:|#)')

  # Repository paths: a top-level folder name at the start of a word (not
  # after another path character), then path characters.
  while IFS=: read -r line path; do
    path="${path#[^A-Za-z]}"
    path="${path%%[.,;:]}"
    path="${path%%[.,;:]}"
    exists "$path" || problem "$page:$line: names a path that does not exist: $path"
  done < <(grep -noE '(^|[^A-Za-z0-9_./-])(mlndt|tools|lab|scripts|tests|examples|benchmarks|python)/[A-Za-z0-9_./*{},-]*' "$page")
done

if ((problems > 0)); then
  echo "check_docs: $problems problem(s)" >&2
  exit 1
fi
echo "check_docs: ok (README.md $readme_lines lines; ${#pages[@]} pages' links and paths exist)"
