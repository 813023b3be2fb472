# Sourced by the benchmark scripts, in the repository root: the build folder ($1, default
# build/ci), the runs per figure ($2, default 3), the gdpn binary, a scratch folder `work`
# removed on exit, and `median` of the numbers on its input.
build=${1:-build/ci}
repeats=${2:-3}
gdpn="$PWD/$build/apps/gdpn/gdpn"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
