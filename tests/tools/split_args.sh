# Sourced by the loopback test scripts (serve_and_send.sh, send_and_replay.sh).
# split_args "MARKERS" ARGS...: each argument after a marker --NAME (NAME one
# of the space-separated MARKERS) is appended to the array NAME_args, which
# the caller has declared; arguments before the first marker are dropped.
split_args() {
  local markers=" $1 " mode="" a
  shift
  for a in "$@"; do
    if [[ $a == --* && $markers == *" ${a#--} "* ]]; then
      mode=${a#--}
    elif [ -n "$mode" ]; then
      eval "${mode}_args+=(\"\$a\")"
    fi
  done
}
