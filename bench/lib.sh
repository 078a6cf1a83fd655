# What every bench/*.sh shares, sourced first thing:
#   source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
# Sets `root` (the checkout) and `bench_name` (the script's file name, for
# messages), and gives:
#   bench_parse SPEC... -- "$@"   the options, into the script's variables
#   bench_help                    the script's header comment (its --help)
#   bench_die MESSAGE [CODE]      "NAME: MESSAGE" on stderr, exit CODE (2)
#   bench_need_built DIR TARGET...  die unless each target is built in DIR
#                                 (lattice: DIR/app/lattice; others DIR/bench/TARGET)
#   bench_need_time               die unless GNU time is at /usr/bin/time
#   bench_positive NAME VALUE     die unless VALUE is a positive integer
#   bench_size WxH                check WxH, set bench_width, bench_height and
#                                 bench_size_args (--width W --height H)
#   bench_workdir VAR             a temporary folder in VAR, removed on exit
#   bench_loadavg                 the 1, 5 and 15 minute load averages
#   bench_loaded COMMAND...       COMMAND between two lines of the load average
#   bench_picture BUILD SCENE SIZE FILE  the scene rendered SIZE x SIZE to a PNG
#   bench_median [-f FMT] X...    the median (the mean of the middle two when even)
#   bench_range X...              "min-max"
#   bench_write FILE COMMAND...   COMMAND's output to the terminal and, when
#                                 FILE is not empty, to FILE (atomically)
#
# Method: bench_parse reads a table of options instead of a case statement
# in each script. A SPEC is
#   --name=var            the option takes a value, stored in $var
#   --name+=var           the same, each time given appended to the array var
#   --name:var=value      a flag: present, it sets $var to value
#   @                     positional arguments are allowed, collected in
#                         bench_args (without it they are unknown arguments)
# -h/--help prints the header comment and exits 0; anything else is an
# unknown argument (exit 2). The defaults are the variables' values before
# the call.
# shellcheck shell=bash

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bench_name=$(basename "$0")

bench_die() {
  echo "$bench_name: $1" >&2
  exit "${2:-2}"
}

# The comment block under the #! line, without its leading "# ".
bench_help() {
  sed -n '2,${/^#/!q;p}' "$0" | sed 's/^# \{0,1\}//'
}

bench_parse() {
  local -a specs=()
  while (($#)) && [[ $1 != -- ]]; do specs+=("$1"); shift; done
  (($#)) && shift
  bench_args=()
  local spec assign matched positional=0
  for spec in "${specs[@]}"; do [[ $spec == @ ]] && positional=1; done
  while (($#)); do
    case $1 in -h | --help) bench_help; exit 0 ;; esac
    matched=0
    for spec in "${specs[@]}"; do
      if [[ $spec == "$1+="* ]]; then
        (($# >= 2)) || bench_die "$1 takes a value (see --help)"
        local -n list=${spec#*+=}
        list+=("$2")
        unset -n list
        shift 2
        matched=1
        break
      elif [[ $spec == "$1="* ]]; then
        (($# >= 2)) || bench_die "$1 takes a value (see --help)"
        printf -v "${spec#*=}" '%s' "$2"
        shift 2
        matched=1
        break
      elif [[ $spec == "$1:"* ]]; then
        assign=${spec#*:}
        printf -v "${assign%%=*}" '%s' "${assign#*=}"
        shift
        matched=1
        break
      fi
    done
    ((matched)) && continue
    if [[ $1 == -* ]] || ((!positional)); then bench_die "unknown argument '$1' (see --help)"; fi
    bench_args+=("$1")
    shift
  done
}

bench_need_built() {
  local build=$1 target exe
  shift
  for target in "$@"; do
    exe=$build/bench/$target
    [[ $target == lattice ]] && exe=$build/app/lattice
    [[ -x $exe ]] || bench_die "$exe is missing; build it: cmake --build $build --target $*"
  done
}

bench_need_time() {
  [[ -x /usr/bin/time ]] || bench_die "/usr/bin/time is missing (Debian package 'time'; scripts/setup.sh --bench)"
}

bench_positive() {
  [[ $2 =~ ^[1-9][0-9]*$ ]] || bench_die "$1 takes a positive integer, not '$2'"
}

bench_size() {
  [[ $1 =~ ^([1-9][0-9]*)x([1-9][0-9]*)$ ]] || bench_die "--size takes WxH, e.g. 256x256, not '$1'"
  bench_width=${BASH_REMATCH[1]}
  bench_height=${BASH_REMATCH[2]}
  bench_size_args=(--width "$bench_width" --height "$bench_height")
}

bench_workdir() {
  local dir
  dir=$(mktemp -d)
  printf -v "$1" '%s' "$dir"
  # shellcheck disable=SC2064 # the folder's name is fixed now, on purpose
  trap "rm -rf '$dir'" EXIT
}

bench_loadavg() {
  cut -d' ' -f1-3 /proc/loadavg
}

# bench_picture BUILD SCENE SIZE FILE: the scene rendered by BUILD's lattice at
# SIZE x SIZE on every thread into the PNG FILE, for a bench of a later stage.
bench_picture() {
  [[ -f $2 ]] || bench_die "no scene file $2 (give --scene FILE)"
  "$1/app/lattice" render "$2" --width "$3" --height "$3" -q -o "$4" 2>/dev/null
}

# bench_same_picture A B LATTICE: "identical" when the PNGs A and B are the
# same bytes, "same pixels" when only their encoding differs (LATTICE's
# `diff` finds no pixel apart: a change to the PNG encoder), else "DIFFERENT".
bench_same_picture() {
  if cmp -s "$1" "$2"; then echo identical
  elif "$3" diff "$1" "$2" 2>/dev/null | grep -q '^differing *0 pixels'; then echo "same pixels"
  else echo DIFFERENT; fi
}

# bench_loaded COMMAND...: runs it between two lines of the load average.
bench_loaded() {
  echo "load average before: $(bench_loadavg)"
  "$@"
  echo "load average after: $(bench_loadavg)"
}

bench_median() {
  local format=""
  if [[ ${1:-} == -f ]]; then format=$2; shift 2; fi
  printf '%s\n' "$@" | sort -g | awk -v f="$format" '{ a[NR] = $1 } END {
    m = (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2
    if (f == "") print m; else printf f, m }'
}

bench_range() {
  printf '%s\n' "$@" | sort -g | sed -n '1p;$p' | paste -sd-
}

bench_write() {
  local file=$1
  shift
  if [[ -z $file ]]; then
    "$@"
    return
  fi
  mkdir -p "$(dirname "$file")"
  "$@" | tee "$file.tmp-$$"
  mv "$file.tmp-$$" "$file"
}
