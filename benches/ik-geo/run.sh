#!/usr/bin/env bash
# Times our compiled inverse kinematics against ik-geo 0.1.2 (see README.md) and writes
# benches/ik-geo/RESULTS.md. ik-geo's nlopt dependency builds with cmake: installed here if
# missing (apt-get, so Debian or Ubuntu, as root or with sudo).
#
# Usage (from anywhere): bash benches/ik-geo/run.sh [extra cargo bench arguments]
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)

if ! command -v cmake > /dev/null; then
    sudo=""
    if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
    $sudo apt-get update
    $sudo apt-get install -y cmake
fi

cd "$root"
cargo bench --manifest-path benches/ik-geo/Cargo.toml "$@"
