#!/bin/sh
# Stands in for the compiler the conformance suite's script calls: instead of building its
# client, it puts the client named by PREBUILT_CLIENT (built beforehand by a user's kind
# of project) where the script's `-o` asks for it.
set -eu
while [ $# -gt 0 ]; do
    if [ "$1" = -o ]; then
        cp "${PREBUILT_CLIENT:?the prebuilt client}" "$2"
        exit 0
    fi
    shift
done
echo "prebuilt-client.sh: no -o in the command line" >&2
exit 2
