# Sourced by the scripts that fetch Debian packages for the project's own use (the engine,
# the VM tests' kernels): apt with a private state, so that the system's apt configuration
# is never read or written.
#   apt_private_init STATE SUITE   a sources list for SUITE of the system's Debian mirror
#                                  (deb.debian.org when it names none); fails without the
#                                  archive keyring
#   apt_mirror                     prints that mirror
#   apt_opts CACHE                 sets the array opts: the options that make apt use STATE
#                                  and CACHE
apt_state=""
keyring=/usr/share/keyrings/debian-archive-keyring.gpg

# The same Debian mirror the system uses where it names one (active lines only).
apt_mirror() {
  local mirror
  mirror=$(cat /etc/apt/sources.list /etc/apt/sources.list.d/*.list \
    /etc/apt/sources.list.d/*.sources 2>/dev/null |
    sed -nE 's,^(deb[[:space:]]+(\[[^]]*\][[:space:]]+)?|URIs:[[:space:]]+)(https?://[^[:space:]]+/debian)/?([[:space:]].*)?$,\3,p' |
    head -n 1 || true)
  echo "${mirror:-http://deb.debian.org/debian}"
}

apt_private_init() {
  apt_state=$1
  local suite=$2 mirror
  [[ -r $keyring ]] || {
    echo "missing $keyring: install the 'debian-archive-keyring' package" >&2
    return 1
  }
  mirror=$(apt_mirror)
  mkdir -p "$apt_state/lists/partial" "$apt_state/etc"
  [[ -f $apt_state/status ]] || : >"$apt_state/status"
  echo "deb [signed-by=$keyring] $mirror $suite main" >"$apt_state/etc/sources.list"
}

apt_opts() {
  local cache=$1
  opts=(
    -o "Dir::Etc::SourceList=$apt_state/etc/sources.list"
    -o "Dir::Etc::SourceParts=/dev/null"
    -o "Dir::Etc::Preferences=/dev/null"
    -o "Dir::Etc::PreferencesParts=/dev/null"
    -o "Dir::State::Lists=$apt_state/lists"
    -o "Dir::State::status=$apt_state/status"
    -o "Dir::Cache=$cache"
    -o "APT::Architecture=amd64"
    -o "APT::Architectures::=amd64"
    -o "APT::Get::List-Cleanup=0"
    -o "Debug::NoLocking=1"
  )
  # Root would otherwise hand downloads to the _apt user, who cannot write our folders.
  [[ $(id -u) -eq 0 ]] && opts+=(-o "APT::Sandbox::User=root")
  return 0
}
