# Sourced by the tools that need a program from Debian: `require_command COMMAND PACKAGE` installs PACKAGE with
# apt-get (through sudo unless root) when COMMAND is missing.
require_command() {
  command -v "$1" >/dev/null 2>&1 && return 0
  local sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  echo "$(basename "$0"): installing $2" >&2
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "$2"
}
