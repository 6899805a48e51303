#!/bin/sh
# write_failure_keeps_file.sh LATTICE_TOOL LATTICE FOLDER: for each format the
# tools write, an output that fails half-way (past a file size limit, as on a
# full disk) must make the tool exit with status 1 and "cannot write 'FILE'",
# leave the file written by the run before unchanged, and leave no temporary
# file. VTK's PLY and OBJ writers and the XML writer's executive report no
# such failure themselves: before latticekit wrote through lkapp's atomic
# files, they left a truncated file and exit status 0.
tool="$1"
lattice="$2"
folder="$3"
rm -rf "$folder" && mkdir -p "$folder" || exit 1
failed=0
for ext in vtp vtk stl ply obj gltf; do
  out="$folder/surface.$ext"
  "$tool" "$lattice" -o "$out" --resolution 2 -q > /dev/null || { echo "$ext: the small surface was not written"; exit 1; }
  cp "$out" "$folder/before.$ext"
  # 100 blocks of 512 bytes: the surface at resolution 32 is larger in every format.
  message=$(ulimit -f 100; "$tool" "$lattice" -o "$out" --resolution 32 -q 2>&1 > /dev/null)
  status=$?
  if [ "$status" -ne 1 ]; then
    echo "$ext: exit status $status, not 1"; failed=1
  fi
  case "$message" in
    *"cannot write '$out'"*) ;;
    *) echo "$ext: the message lacks \"cannot write '$out'\": $message"; failed=1 ;;
  esac
  if ! cmp -s "$out" "$folder/before.$ext"; then
    echo "$ext: the earlier file was changed"; failed=1
  fi
  rm -f "$folder/before.$ext"
  echo "$ext: $message"
done
left=$(ls -A "$folder" | grep partial)
if [ -n "$left" ]; then
  echo "temporary files left: $left"; failed=1
fi
exit $failed
