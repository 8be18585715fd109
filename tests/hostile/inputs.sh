# shellcheck shell=bash disable=SC2154,SC2034,SC2059  # lib.sh sets the variables; printf formats are built on purpose
# The hostile sweep's input classes (sourced by lab/scripts/hostile-sweep after tests/hostile/lib.sh):
# files that cost far more than they weigh (1), files that are not files or are too
# big (3), ascii data lines that do not parse (5) and scans whose metric size the model must hold
# (6). Every file is made here, byte by byte.

sweepClass 1 "inputs that cost far more than they weigh"
sweepClass 3 "inputs of the wrong kind or size, every reader"
sweepClass 5 "ascii data lines that do not parse"
sweepClass 6 "metric size out of the model's range (refused or stored right)"

# Four bytes, little-endian.
le32() {
  local n=$1 i
  for i in 0 8 16 24; do printf "\\$(printf %03o $(((n >> i) & 255)))"; done
}
# The same as printf escapes (\ooo), for a printf that writes them later: a command substitution
# of le32 would drop its zero bytes.
le32Escaped() {
  local n=$1 i
  for i in 0 8 16 24; do printf '\\%03o' $(((n >> i) & 255)); done
}

# A PCD header: pcdHeader FIELDS SIZE TYPE COUNT WIDTH HEIGHT POINTS DATA.
pcdHeader() {
  printf 'VERSION 0.7\nFIELDS %s\nSIZE %s\nTYPE %s\nCOUNT %s\nWIDTH %s\nHEIGHT %s\n' "$1" "$2" "$3" "$4" "$5" "$6"
  printf 'VIEWPOINT 0 0 0 1 0 0 0\nPOINTS %s\nDATA %s\n' "$7" "$8"
}
xyzHeader() { pcdHeader "x y z" "4 4 4" "F F F" "1 1 1" "$1" 1 "$1" "$2"; }

# --- 1: declared sizes the bytes present cannot back -------------------------------------------
I1=$IN/cost
mkdir -p "$I1"
# The issue's own: 188 bytes whose POINTS and uncompressed size agree (1.2 GB of points).
{ xyzHeader 100000000 binary_compressed; le32 100; le32 1200000000; head -c 100 /dev/urandom; } >"$I1/agreeing_sizes.pcd"
{ xyzHeader 1000 binary_compressed; le32 8; le32 4294967295; head -c 8 /dev/urandom; } >"$I1/max_uncompressed.pcd"
{ xyzHeader 1000 binary_compressed; le32 100; le32 12000; head -c 100 /dev/urandom; } >"$I1/past_lzf_ratio.pcd"
{ xyzHeader 1000 binary_compressed; le32 4000000000; le32 12000; head -c 16 /dev/urandom; } >"$I1/compressed_past_file.pcd"
{ xyzHeader 2000000000 binary; head -c 24 /dev/urandom; } >"$I1/binary_points.pcd"
{ xyzHeader 4000000000 ascii; echo "1 2 3"; } >"$I1/ascii_points.pcd"
{ pcdHeader "x y z" "4 4 4" "F F F" "1 1 1" 65536 65537 4295032832 binary; head -c 24 /dev/urandom; } >"$I1/width_times_height.pcd"
{ pcdHeader "x y z junk" "4 4 4 4" "F F F F" "1 1 1 100000000" 1 1 1 binary; head -c 64 /dev/urandom; } >"$I1/huge_count.pcd"
{ printf 'ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\nproperty float y\n'
  printf 'property float z\nend_header\n'; head -c 12 /dev/urandom; } >"$I1/ply_vertices.ply"
{ printf 'ply\nformat ascii 1.0\nelement vertex 1000000000\nproperty float x\nproperty float y\nproperty float z\n'
  printf 'end_header\n1 2 3\n'; } >"$I1/ply_ascii_vertices.ply"
{ printf 'ply\nformat binary_little_endian 1.0\nelement face 4000000000\nproperty list uchar int vertex_indices\n'
  printf 'element vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n'; head -c 64 /dev/urandom; } >"$I1/ply_faces_first.ply"
{ printf 'ply\nformat binary_little_endian 1.0\nelement vertex 100000\n'
  seq -f 'property float p%g' 1 30000
  printf 'property float x\nproperty float y\nproperty float z\nend_header\n'; head -c 64 /dev/urandom; } >"$I1/ply_many_properties.ply"
repeat() { yes "$1" | head -n "$2" | tr '\n' ' '; }
{ printf 'VERSION 0.7\nFIELDS x y z %s\n' "$(seq -f 'f%g' -s ' ' 1 40000)"
  printf 'SIZE 4 4 4 %s\nTYPE F F F %s\nCOUNT 1 1 1 %s\n' "$(repeat 4 40000)" "$(repeat F 40000)" "$(repeat 1 40000)"
  printf 'WIDTH 1000000\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 1000000\nDATA binary\n'; head -c 64 /dev/urandom; } >"$I1/many_fields.pcd"
refuse 1 q:pcd_agreeing_sizes "agreeing_sizes.pcd" "$PREPARE" "$I1/agreeing_sizes.pcd" -o "$W/work/out/p" --name m
for scan in max_uncompressed.pcd past_lzf_ratio.pcd compressed_past_file.pcd binary_points.pcd ascii_points.pcd \
  width_times_height.pcd huge_count.pcd ply_vertices.ply ply_ascii_vertices.ply ply_faces_first.ply \
  ply_many_properties.ply many_fields.pcd; do
  refuse 1 "${scan%.*}" "$scan" "$PREPARE" "$I1/$scan" -o "$W/work/out/p" --name m
done
refuse 1 tradeoff_agreeing_sizes "agreeing_sizes.pcd" "$TRADEOFF" "$I1/agreeing_sizes.pcd" -o "$W/work/out/t"
# Model files whose level table declares more than the file holds.
patchBytes() {  # patchBytes FILE OFFSET BYTES...: a copy of good.oct with bytes replaced
  cp "$IN/good.oct" "$1"
  printf "$3" | dd of="$1" bs=1 seek="$2" conv=notrunc status=none
}
levelTable() {  # levelTable FILE: the offset of a .oct's level table (docs/format.md)
  local version
  version=$(od -An -tu2 -j4 -N2 "$1" | tr -d ' ')
  if [ "$version" = 1 ]; then
    echo 784
  else  # version 2: 788 bytes, then 6 per normal palette entry; versions 4 and 6: the placement
    echo $((788 + 6 * $(od -An -tu2 -j18 -N2 "$1" | tr -d ' ') + (version >= 4 ? 40 : 0)))
  fi
}
patchBytes "$I1/huge_level.oct" $(($(levelTable "$IN/good.oct") + 4)) '\377\377\377\377'
patchBytes "$I1/huge_leaves.oct" $(($(levelTable "$IN/good.oct") + 8)) '\377\377\377\377'
patchBytes "$I1/many_levels.oct" 6 '\377'
refuse 1 q:oct_huge_level "huge_level.oct" "$RENDER" --file "$I1/huge_level.oct" -o "$W/work/out/x.png"
refuse 1 oct_huge_leaves "huge_leaves.oct" "$RENDER" --file "$I1/huge_leaves.oct" -o "$W/work/out/x.png"
refuse 1 oct_many_levels "many_levels.oct" "$RENDER" --file "$I1/many_levels.oct" -o "$W/work/out/x.png"
# Model files of 900 MB and 1 GiB (sparse) behind a real header that lies: refused from the header,
# before the body is read (the check reads 4 KiB, where reading first cost 2.1 GB and 14 s).
"$PREPARE" "$IN/good.pcd" -o "$META/chunked" --name ball --depths 5,6 --chunked >/dev/null ||
  { echo "hostile-sweep: cannot prepare the chunked model" >&2; exit 1; }
asVersion1() {  # asVersion1 V2_FILE: the same model as a version 1 file (no normals; docs/format.md)
  local table
  table=$(levelTable "$1")
  printf 'OCTP\001\000'; dd if="$1" bs=1 skip=6 count=1 status=none; printf '\000'; le32 1000
  dd if="$1" bs=1 skip=16 count=2 status=none; printf '\000\000'
  dd if="$1" bs=1 skip=20 count=768 status=none; tail -c +$((table + 1)) "$1"
}
asVersion1 "$IN/good.oct" >"$I1/v1.oct"
for size in 900000000 1G; do
  for model in good.oct chunked; do
    source_file=$IN/good.oct
    [ "$model" = chunked ] && source_file=$META/chunked/ball.oct
    cp "$source_file" "$I1/${model%.oct}_$size.oct"
    truncate -s "$size" "$I1/${model%.oct}_$size.oct"
  done
  cp "$I1/v1.oct" "$I1/v1_$size.oct"
  truncate -s "$size" "$I1/v1_$size.oct"
  # Sizes that add up to the file, in a level no tree of its depth can have.
  bytes=$(stat -c %s "$I1/good_$size.oct")
  table=$(levelTable "$IN/good.oct")
  levels=$(od -An -tu1 -j6 -N1 "$IN/good.oct" | tr -d ' ')
  rest=$(for ((i = 1; i < levels; i++)); do
    od -An -tu4 -j$((table + 12 * i + 4)) -N8 "$IN/good.oct"; done | awk '{ s += $1 + $2 } END { print s + 0 }')
  leaves=$(od -An -tu4 -j$((table + 8)) -N4 "$IN/good.oct" | tr -d ' ')
  cp "$I1/good_$size.oct" "$I1/sizes_agree_$size.oct"
  le32 $((bytes - table - 12 * levels - rest - leaves)) |
    dd of="$I1/sizes_agree_$size.oct" bs=1 seek=$((table + 4)) conv=notrunc status=none
done
q=q:
for size in 1G 900000000; do
  refuse 1 "${q}oct_lie_$size" "declared sizes do not match" "$RENDER" --file "$I1/good_$size.oct" -o "$W/work/out/x.png"
  q=""
  refuse 1 "oct_v1_lie_$size" "declared sizes do not match" "$RENDER" --file "$I1/v1_$size.oct" -o "$W/work/out/x.png"
  refuse 1 "oct_sizes_agree_$size" "impossible for the depth" "$RENDER" --file "$I1/sizes_agree_$size.oct" -o "$W/work/out/x.png"
  refuse 1 "chunked_lie_$size" "file size does not fit" "$RENDER" --file "$I1/chunked_$size.oct" -o "$W/work/out/x.png"
  if [ -n "$VIEW" ]; then
    refuse 1 "view_oct_lie_$size" "declared sizes do not match" env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER \
      "$VIEW" --file "$I1/good_$size.oct"
    refuse 1 "view_chunked_$size" "cannot be shown here" env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER \
      "$VIEW" --file "$I1/chunked_$size.oct"
  fi
done

# LAZ whose header, LASzip VLR or chunk table lies, and whose chunks are corrupt: refused from the
# chunk table, or at the first chunk whose arithmetic code runs past its bytes (make_large_scan
# writes the good LAZ: 3000 points in chunks of 1000).
MAKE_SCAN=$(dirname "$PREPARE")/../tests/support/make_large_scan
if [ -x "$MAKE_SCAN" ]; then
  "$MAKE_SCAN" --points 3000 --format laz --las-format 3 --varied-fields --chunk-points 1000 \
    -o "$IN/good.laz" >/dev/null || { echo "hostile-sweep: cannot write good.laz" >&2; exit 1; }
  laz_points=$(od -An -tu4 -j96 -N4 "$IN/good.laz" | tr -d ' ')
  laz_vlr=$(($(grep -boa 'laszip encoded' "$IN/good.laz" | head -n 1 | cut -d: -f1) - 2 + 54))
  lazCopy() {  # lazCopy NAME OFFSET BYTES [GOOD]: good.laz (or GOOD) with bytes replaced
    cp "${4:-$IN/good.laz}" "$I1/$1"
    printf "$3" | dd of="$I1/$1" bs=1 seek="$2" conv=notrunc status=none
  }
  lazCopy laz_count_4e9.laz 107 '\000\050\153\356'       # 4,000,000,000 points
  lazCopy laz_no_table.laz "$laz_points" "$(le32 "$laz_points")\000\000\000\000"  # interrupted
  lazCopy laz_huge_chunks.laz $((laz_vlr + 12)) '\000\000\020\000'  # chunks of 2^20 points
  lazCopy laz_corrupt.laz $((laz_points + 8 + 200)) '\125\252\125\252\125\252\125\252'
  cp "$IN/good.laz" "$I1/laz_cut.laz"
  truncate -s $(($(stat -c %s "$IN/good.laz") / 2)) "$I1/laz_cut.laz"
  refuse 1 q:laz_count_4e9 "the header declares 4000000000 points" "$PREPARE" "$I1/laz_count_4e9.laz" -o "$W/work/out/p" --name m
  refuse 1 laz_no_table "no chunk table" "$PREPARE" "$I1/laz_no_table.laz" -o "$W/work/out/p" --name m
  refuse 1 laz_huge_chunks "chunks of 1048576, the chunk table lists 3" "$PREPARE" "$I1/laz_huge_chunks.laz" -o "$W/work/out/p" --name m
  refuse 1 q:laz_corrupt "corrupt LAZ" "$PREPARE" "$I1/laz_corrupt.laz" -o "$W/work/out/p" --name m
  refuse 1 laz_cut "lies outside the point data" "$PREPARE" "$I1/laz_cut.laz" -o "$W/work/out/p" --name m
  # Layered LAZ (point format 7: a chunk is its first point raw, 36 bytes, its point count, ten
  # 32-bit layer sizes, the layers): a layer size past the chunk, sizes that cut the layers
  # elsewhere, a corrupt layer, a point count that is not the chunk table's.
  "$MAKE_SCAN" --points 3000 --format laz --las-format 7 --varied-fields --chunk-points 1000 \
    -o "$IN/good7.laz" >/dev/null || { echo "hostile-sweep: cannot write good7.laz" >&2; exit 1; }
  head7=$(($(od -An -tu4 -j96 -N4 "$IN/good7.laz" | tr -d ' ') + 8 + 36))  # the point count
  z7=$(od -An -tu4 -j$((head7 + 8)) -N4 "$IN/good7.laz" | tr -d ' ')
  class7=$(od -An -tu4 -j$((head7 + 12)) -N4 "$IN/good7.laz" | tr -d ' ')
  lazCopy laz7_layer_huge.laz $((head7 + 4)) '\377\377\377\377' "$IN/good7.laz"
  lazCopy laz7_layer_shift.laz $((head7 + 8)) "$(le32Escaped $((z7 - 3)))$(le32Escaped $((class7 + 3)))" "$IN/good7.laz"
  lazCopy laz7_corrupt.laz $((head7 + 44 + 100)) '\125\252\125\252\125\252\125\252' "$IN/good7.laz"
  lazCopy laz7_count.laz "$head7" "$(le32Escaped 999)" "$IN/good7.laz"
  refuse 1 q:laz7_layer_huge "layer 1 of 10 has 4294967295 bytes" "$PREPARE" "$I1/laz7_layer_huge.laz" -o "$W/work/out/p" --name m
  refuse 1 laz7_layer_shift "corrupt LAZ: the POINT14 layer z does not end where its size says" "$PREPARE" "$I1/laz7_layer_shift.laz" -o "$W/work/out/p" --name m
  refuse 1 laz7_corrupt "corrupt LAZ" "$PREPARE" "$I1/laz7_corrupt.laz" -o "$W/work/out/p" --name m
  refuse 1 laz7_count "the chunk says it has 999 points" "$PREPARE" "$I1/laz7_count.laz" -o "$W/work/out/p" --name m
  # COPC (its info VLR first, at byte 375 + 54; nodes of at most 100 points, so child pages): a
  # root cube of negative size, a root page past the file, a key deeper than any octree, the root
  # node without points (its chunk then belongs to no node).
  "$MAKE_SCAN" --points 3000 --format laz --las-format 7 --copc --chunk-points 100 \
    -o "$IN/good.copc.laz" >/dev/null || { echo "hostile-sweep: cannot write good.copc.laz" >&2; exit 1; }
  copc_root=$(od -An -tu8 -j$((429 + 40)) -N8 "$IN/good.copc.laz" | tr -d ' ')
  lazCopy copc_half.laz $((429 + 24)) '\000\000\000\000\000\000\360\277' "$IN/good.copc.laz"  # -1.0
  lazCopy copc_root_past.laz $((429 + 48)) '\000\000\000\000\000\001\000\000' "$IN/good.copc.laz"
  lazCopy copc_level.laz "$copc_root" "$(le32Escaped 99)" "$IN/good.copc.laz"
  lazCopy copc_no_root.laz $((copc_root + 28)) "$(le32Escaped 0)" "$IN/good.copc.laz"
  refuse 1 q:copc_half "absurd COPC root cube: half size -1" "$PREPARE" "$I1/copc_half.laz" -o "$W/work/out/p" --name m
  refuse 1 copc_root_past "a hierarchy page of 1099511627776 bytes" "$PREPARE" "$I1/copc_root_past.laz" -o "$W/work/out/p" --name m
  refuse 1 q:copc_level "octree level 99 (0 to 24 are read)" "$PREPARE" "$I1/copc_level.laz" -o "$W/work/out/p" --name m
  refuse 1 copc_no_root "nodes with points" "$PREPARE" "$I1/copc_no_root.laz" -o "$W/work/out/p" --name m
fi

# --- 3: not a regular file, or past the stated size, for every tool that reads one -------------
I3=$IN/kind
mkdir -p "$I3/directory"
mkfifo "$I3/fifo"
ln -s loop_b "$I3/loop_a"
ln -s loop_a "$I3/loop_b"
ln -s nowhere "$I3/dangling"
ln -s fifo "$I3/link_to_fifo"
truncate -s 2G "$I3/sparse_2g.pcd"  # no blocks on disk: 2 GiB of zeros to a reader
truncate -s 2M "$I3/sparse_2m.json"
: >"$I3/empty"
kinds=(/dev/zero fifo directory loop_a dangling link_to_fifo sparse_2g.pcd empty)
expect_of() {
  case $1 in
    /dev/zero) echo "is a character device" ;; fifo | link_to_fifo) echo "is a FIFO" ;;
    directory) echo "is a directory" ;; loop_a) echo "symlink loop" ;; dangling) echo "dangling symbolic link" ;;
    sparse_2g.pcd) echo "2147483648 bytes, more than the 1" ;; empty) echo "empty" ;; block) echo "is a block device" ;;
    socket) echo "is a socket" ;; *) echo "$1" ;;
  esac
}
if [ "$can_mknod" -eq 1 ]; then  # devices of our own: never the system's /dev nodes as outputs
  mknod "$I3/block" b 7 250 && kinds+=(block)
fi
[ -n "$socket" ] && ln "$socket" "$I3/socket" && kinds+=(socket)
for kind in "${kinds[@]}"; do
  path=$kind
  [[ $kind == /* ]] || path=$I3/$kind
  tag=${kind##*/}
  expected=$(expect_of "$kind")
  q=""
  [ "$kind" = fifo ] && q="q:"
  scan_expected=$expected  # the streamed preparer takes scans of up to 4 TiB: read by the header
  [ "$kind" = sparse_2g.pcd ] && scan_expected="header ends before its 'DATA' line"
  refuse 3 "${q}prepare_scan_$tag" "$scan_expected" "$PREPARE" "$path" -o "$W/work/out/p" --name m
  refuse 3 "prepare_scene_$tag" "$expected" "$PREPARE" "$IN/good.pcd" --scene "$path" -o "$W/work/out/p" --name m
  refuse 3 "${q}render_file_$tag" "$expected" "$RENDER" --file "$path" -o "$W/work/out/x.png"
  refuse 3 "tradeoff_scan_$tag" "$expected" "$TRADEOFF" "$path" -o "$W/work/out/t"
  city_expected=$expected  # a scene file (docs/city.md) holds at most 64 MiB of JSON text
  [ "$kind" = sparse_2g.pcd ] && city_expected="2147483648 bytes, more than the 64 MiB"
  [ "$kind" = empty ] && city_expected="not valid JSON"
  refuse 3 "${q}render_city_$tag" "$city_expected" "$RENDER" --city "$path" --eye 0,0,-2 -o "$W/work/out/x.png"
  [ -n "$VIEW" ] && refuse 3 "view_file_$tag" "$expected" env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER \
    "$VIEW" --file "$path"
done
refuse 3 q:scene_past_1mib "more than the 1 MiB" "$PREPARE" "$IN/good.pcd" --scene "$I3/sparse_2m.json" \
  -o "$W/work/out/p" --name m
refuse 3 city_nul_bytes "a NUL byte at byte 0" "$RENDER" --city "$I3/sparse_2m.json" --eye 0,0,-2 \
  -o "$W/work/out/x.png"
# Cell tables (docs/city.md, "Visibility cells"): what is no table, or not this scene's, is refused.
printf '{"models": ["good.oct"], "instances": [[0, 0, 0, 0, 0, 0]]}' >"$IN/one_scene.json"
printf 'OCTCELL1\001\000\000\000' >"$I3/short.cells"
head -c 200 /dev/zero | tr '\0' 'x' >"$I3/magic.cells"
{ printf 'OCTCELL1\002\000\000\000'; head -c 200 /dev/zero; } >"$I3/other_scene.cells"
# OCTCELL2 of one cell over the one instance: an order naming instance 1 too, then a cell that
# refers to a cell before the first.
cells2_head() {
  printf 'OCTCELL2\001\000\000\000\001\000\000\000\001\000\000\000\001\000\000\000'
  head -c 16 /dev/zero
  printf '\000\000\000\001\000\000\000\000\000\000\000\377\377\377\377\377'
  head -c 8 /dev/zero
}
{ cells2_head; printf '\003\000\000\000\001\000\001'; head -c 8 /dev/zero; } >"$I3/bad_order.cells"
{ cells2_head; printf '\000\000\000\000\000\000\000\000\002\000\000\000\001\001'; } \
  >"$I3/bad_reference.cells"
refuse 3 q:cells_truncated "short.cells: cell table truncated" "$RENDER" --city "$IN/one_scene.json" \
  --cells "$I3/short.cells" --eye 0,0,-2 -o "$W/work/out/x.png"
refuse 3 cells_bad_magic "no OCTCELL2 or OCTCELL1 magic" "$RENDER" --city "$IN/one_scene.json" \
  --cells "$I3/magic.cells" --eye 0,0,-2 -o "$W/work/out/x.png"
refuse 3 cells_bad_order "instance order malformed" "$RENDER" --city "$IN/one_scene.json" \
  --cells "$I3/bad_order.cells" --eye 0,0,-2 -o "$W/work/out/x.png"
refuse 3 cells_bad_reference "referring to no earlier cell" "$RENDER" --city "$IN/one_scene.json" \
  --cells "$I3/bad_reference.cells" --eye 0,0,-2 -o "$W/work/out/x.png"
refuse 3 cells_other_scene "made for a scene of another instance count" "$RENDER" \
  --city "$IN/one_scene.json" --cells "$I3/other_scene.cells" --eye 0,0,-2 -o "$W/work/out/x.png"
refuse 3 cells_directory "is a directory" "$RENDER" --city "$IN/one_scene.json" --cells "$I3/directory" \
  --eye 0,0,-2 -o "$W/work/out/x.png"
refuse 3 cells_past_64mib "more than the 64 MiB" "$RENDER" --city "$IN/one_scene.json" \
  --cells "$I3/sparse_2g.pcd" --eye 0,0,-2 -o "$W/work/out/x.png"
refuse 3 proc_file_as_scan "status" "$PREPARE" /proc/self/status -o "$W/work/out/p" --name m
refuse 3 dev_urandom_as_model "is a character device" "$RENDER" --file /dev/urandom -o "$W/work/out/x.png"

# --- 5: ascii data lines that do not parse: an error naming the line ---------------------------
I5=$IN/lines
mkdir -p "$I5"
asciiWith() {  # asciiWith NAME LINE: three points, the second one LINE
  { xyzHeader 3 ascii; printf '1 2 3\n%s\n7 8 9\n' "$2"; } >"$I5/$1.pcd"
}
asciiWith word "10.5 10.5 oops"
asciiWith missing_column "10.5 10.5"
asciiWith extra_column "10.5 10.5 1 4"
asciiWith empty_line ""
asciiWith hex "0x10 1 2"
asciiWith comma_decimal "1,5 2 3"
asciiWith trailing_junk "1 2 3x"
asciiWith nul "$(printf '1 2 \0013')"
{ xyzHeader 5 ascii; printf '1 2 3\n4 5 6\n'; } >"$I5/fewer_lines.pcd"
{ printf 'ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n'
  printf 'end_header\n1 2 3\n4 5 oops\n'; } >"$I5/ply_word.ply"
{ printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n'
  printf 'end_header\n1 2 3\n4 5 6\n'; } >"$I5/ply_fewer_lines.ply"
refuse 5 q:word "line 12" "$PREPARE" "$I5/word.pcd" -o "$W/work/out/p" --name m
refuse 5 empty_line "1 blank line, which holds no point (line 12)" "$PREPARE" "$I5/empty_line.pcd" -o "$W/work/out/p" --name m
for scan in missing_column extra_column hex comma_decimal trailing_junk nul; do
  refuse 5 "$scan" "line 12" "$PREPARE" "$I5/$scan.pcd" -o "$W/work/out/p" --name m
done
refuse 5 fewer_lines "truncated: header declares 5 points but the ascii data has 2 data lines" "$PREPARE" "$I5/fewer_lines.pcd" -o "$W/work/out/p" --name m
refuse 5 ply_word "ply_word.ply" "$PREPARE" "$I5/ply_word.ply" -o "$W/work/out/p" --name m
refuse 5 ply_fewer_lines "ply_fewer_lines.ply" "$PREPARE" "$I5/ply_fewer_lines.ply" -o "$W/work/out/p" --name m
refuse 5 tradeoff_word "line 12" "$TRADEOFF" "$I5/word.pcd" -o "$W/work/out/t"

# --- 6: a scan larger than the model's size field or smaller than its unit ---------------------
# Passes when refused as above, or when prepared (exit 0) with the cube edge printed and stored
# (a version 1 .oct keeps micrometres in bytes 8..11, version 2 picometres in bytes 8..15) within 1%
# of the scan's.
metricCase() {  # metricCase NAME EDGE_METRES SCAN
  local name=$1 edge=$2 scan=$3
  selected "$name" || return 0
  out "metric_$name"
  before=$(snapshot)
  measure "$PREPARE" "$scan" -o "$OUT/m" --name m
  problems=""
  if [ "$status" -eq 0 ]; then
    local printed stored version
    printed=$(sed -n 's/.*cube edge \([0-9.e+-]*\) m.*/\1/p' "$META/stdout")
    awk -v p="$printed" -v e="$edge" 'BEGIN { exit !(p > 0.99 * e && p < 1.01 * e) }' ||
      problems+=" printed cube edge '$printed' m, the scan's is $edge m"
    version=$(od -An -tu2 -j4 -N2 "$OUT/m/m.oct" | tr -d ' ')
    if [ "$version" = 1 ]; then
      stored=$(od -An -tu4 -j8 -N4 "$OUT/m/m.oct" | tr -d ' ')
      awk -v s="$stored" -v e="$edge" 'BEGIN { exit !(s > 0.99e6 * e && s < 1.01e6 * e) }' ||
        problems+=" stored ${stored} um, the scan's edge is $edge m"
    else
      stored=$(od -An -tu8 -j8 -N8 "$OUT/m/m.oct" | tr -d ' ')
      awk -v s="$stored" -v e="$edge" 'BEGIN { exit !(s > 0.99e12 * e && s < 1.01e12 * e) }' ||
        problems+=" stored ${stored} pm, the scan's edge is $edge m"
    fi
    rm -rf "$OUT/m"
    before=$(snapshot)  # a model written on purpose is not a leftover
  else
    [ "$status" -eq 1 ] || problems+=" exit status $status"
    [ "$lines" -eq 1 ] || problems+=" $lines lines on stderr (want 1)"
  fi
  judgeCost
  recordCase 6 "$name" "$problems"
}
I6=$IN/metric
mkdir -p "$I6"
{ xyzHeader 3 ascii; printf '0 0 0\n5000 1 1\n2500 3 2\n'; } >"$I6/five_km.pcd"
{ xyzHeader 3 ascii; printf '0 0 0\n1e6 1 1\n-1e6 3 2\n'; } >"$I6/two_thousand_km.pcd"
{ xyzHeader 3 ascii; printf '0 0 0\n0.0000002 0 0\n0 0.0000001 0\n'; } >"$I6/sub_micrometre.pcd"
metricCase five_km 5000 "$I6/five_km.pcd"
metricCase two_thousand_km 2000000 "$I6/two_thousand_km.pcd"
metricCase sub_micrometre 0.0000002 "$I6/sub_micrometre.pcd"
