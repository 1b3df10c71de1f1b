#!/bin/bash
# Runs a command in a fresh cgroup v1 or v2 memory group limited to BYTES:
#   in_memory_group.sh BYTES COMMAND...
# The command sees the limit as OSM_TEST_MEMORY_GROUP_BYTES. Exits 77 (CTest's
# skip) where no such group can be made: not root, or no writable memory
# controller (a cgroup v2 system that does not delegate it, for example).
set -u
bytes=$1
shift
skip() {
  echo "skipped: $*"
  exit 77
}
[ "$(id -u)" = 0 ] || skip "not root: cannot make a control group"
v1=$(awk -F: '$2 ~ /(^|,)memory(,|$)/ { print $3 }' /proc/self/cgroup)
if [ -n "$v1" ] && [ -d /sys/fs/cgroup/memory ]; then
  group=/sys/fs/cgroup/memory${v1%/}/osm-test-$$
  file=memory.limit_in_bytes
else
  v2=$(awk -F: '$1 == 0 && $2 == "" { print $3 }' /proc/self/cgroup)
  [ -n "$v2" ] && [ -f /sys/fs/cgroup/cgroup.controllers ] || skip "no memory controller"
  group=/sys/fs/cgroup${v2%/}/osm-test-$$
  file=memory.max
fi
mkdir "$group" 2>/dev/null || skip "cannot make $group"
trap 'rmdir "$group" 2>/dev/null' EXIT
echo "$bytes" > "$group/$file" 2>/dev/null || skip "cannot limit $group"
# The command runs in a child shell moved into the group, so that this one
# stays outside and can remove the group once it is empty.
OSM_TEST_MEMORY_GROUP_BYTES=$bytes bash -c 'echo $$ > "$1/cgroup.procs" || exit 77; shift; exec "$@"' \
  - "$group" "$@"
