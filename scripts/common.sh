# Shared by run.sh and test.sh: install what is missing, configure and build a preset.
# Sourced, not executed.

PHASEBOX_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# libav*-dev and libgif-dev encode clips (MP4 and GIF); ffmpeg gives the tests ffprobe.
# qt6-l10n-tools and qt6-tools-dev: lupdate, lrelease and CMake's LinguistTools (the
# translations); qt6-translations-l10n: Qt's own strings (standard buttons) in those languages.
PHASEBOX_PACKAGES=(cmake ninja-build g++ qt6-base-dev libqt6opengl6-dev qt6-charts-dev
                   qt6-svg-dev qt6-l10n-tools qt6-tools-dev qt6-translations-l10n libeigen3-dev
                   libgl1-mesa-dev xvfb xauth pkg-config
                   libavcodec-dev libavformat-dev libswscale-dev libavutil-dev libgif-dev ffmpeg)

phasebox_log() { printf '[phasebox] %s\n' "$*" >&2; }

# phasebox_install_packages PACKAGE...: installs those of the given Debian packages that are
# not installed yet (scripts/check-format.sh uses it for clang-format alone).
phasebox_install_packages() {
    local missing=()
    local pkg
    for pkg in "$@"; do
        if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q 'install ok installed'; then
            missing+=("$pkg")
        fi
    done
    if [ ${#missing[@]} -eq 0 ]; then
        return 0
    fi
    phasebox_log "installing missing packages: ${missing[*]}"
    local sudo=""
    if [ "$(id -u)" -ne 0 ]; then
        sudo="sudo"
    fi
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get update -q >/dev/null
    $sudo apt-get install -y -q --no-install-recommends "${missing[@]}" >/dev/null
}

# Installs only the packages of the build (and any given as arguments) not installed yet.
phasebox_install_dependencies() {
    phasebox_install_packages "${PHASEBOX_PACKAGES[@]}" "$@"
}

# phasebox_build PRESET [TARGET...]
phasebox_build() {
    local preset="$1"
    shift
    cd "$PHASEBOX_ROOT"
    if [ ! -f "build/$preset/CMakeCache.txt" ]; then
        phasebox_log "configuring preset $preset"
        cmake --preset "$preset" >/dev/null
    fi
    phasebox_log "building preset $preset"
    if [ $# -gt 0 ]; then
        cmake --build --preset "$preset" --target "$@"
    else
        cmake --build --preset "$preset"
    fi
}
