# shellcheck shell=bash disable=SC2154,SC2034,SC2059  # lib.sh sets the variables; printf formats are built on purpose
# The hostile sweep's option and scene classes (sourced by lab/scripts/hostile-sweep after
# tests/hostile/lib.sh): scenes that ask for unbounded work (2), outputs too large
# (4), numbers that would wrap or truncate (7), model names the generated sources cannot carry
# (8), octopoint-tradeoff's --depths and --fraction-bits (11) and what the messages say (12).

sweepClass 2 "scenes within range that ask for unbounded work"
sweepClass 4 "output images too large"
sweepClass 7 "numbers that would wrap, truncate or carry junk"
sweepClass 8 "model names the generated sources cannot carry"
sweepClass 11 "octopoint-tradeoff --depths and --fraction-bits"
sweepClass 12 "messages: true, pointing at the cause, readable"

P_OUT=$W/work/out/p
X_PNG=$W/work/out/x.png
T_OUT=$W/work/out/t

# --- 2: scenes ------------------------------------------------------------------------------
I2=$IN/scenes
mkdir -p "$I2"
scene() {  # scene CLASS NAME EXPECTED JSON
  printf '%s\n' "$4" >"$I2/${2#q:}.json"
  refuse "$1" "$2" "$3" "$PREPARE" "$IN/good.pcd" --scene "$I2/${2#q:}.json" -o "$P_OUT" --name m
}
scene 2 q:fine_angle_step "raise angle_step" '{"yaw": [-180, 180], "pitch": [-90, 90], "angle_step": 0.1}'
scene 2 big_framebuffer "shrink the framebuffer" '{"yaw": [-180, 180], "pitch": [-90, 90], "framebuffer": [8192, 8192]}'
scene 2 fine_zoom_step "zoom_step" \
  '{"yaw": [-180, 180], "pitch": [-90, 90], "zoom": [0.001, 32767], "zoom_step": 1.01, "angle_step": 1}'
scene 2 everything_small_steps "views" \
  '{"yaw": [-180, 180], "pitch": [-90, 90], "roll": 0, "zoom": [1, 16], "zoom_step": 1.01, "angle_step": 0.5}'
viewpoints=$(awk 'BEGIN { for (i = 1; i <= 20000; i++) printf "{\"yaw\": %d, \"pitch\": 0},", i % 360 - 180 }')
scene 2 many_viewpoints_big_frames "shrink the framebuffer" \
  "{\"viewpoints\": [${viewpoints%,}], \"framebuffer\": [8192, 8192], \"zoom\": [1, 32767]}"
eyes=$(awk 'BEGIN { for (i = 1; i <= 20000; i++) printf "{\"eye\": [%d, 0, 0]},", i % 100 }')
scene 2 many_eyes_big_frames "fewer eyes or path_frames" \
  "{\"eyes\": [${eyes%,}], \"framebuffer\": [8192, 8192]}"

# --- 4: output size -------------------------------------------------------------------------
refuse 4 q:render_8192_square "at most 16777216" "$RENDER" --size 8192x8192 -o "$X_PNG"
refuse 4 render_sheet_36_8192 "--size" "$RENDER" --sheet 36 --size 8192x8192 -o "$X_PNG"
refuse 4 render_sheet_36_1024 "at most 16777216" "$RENDER" --sheet 36 --size 1024x1024 -o "$X_PNG"
refuse 4 render_4097x4096 "at most 16777216" "$RENDER" --size 4097x4096 -o "$X_PNG"
refuse 4 render_side_past_8192 "--size" "$RENDER" --size 8193x1 -o "$X_PNG"
refuse 4 tradeoff_8192_square "at most 16777216" "$TRADEOFF" "$IN/good.pcd" --size 8192x8192 -o "$T_OUT"
refuse 4 tradeoff_sizes "at most 16777216" "$TRADEOFF" "$IN/good.pcd" --sweep-views --sizes 64x48,8192x8192 -o "$T_OUT"
[ -n "$VIEW" ] && refuse 4 view_8192_square "--size" env -u DISPLAY "$VIEW" --size 8192x8192

# --- 7: numbers -----------------------------------------------------------------------------
num() {  # num NAME EXPECTED TOOL ARGS...: a bad number; the message names the option
  refuse 7 "$@"
}
num q:size_wraps "--size" "$RENDER" --size 4294967616x240 -o "$X_PNG"
num depth_fraction "--depth: '8.7'" "$RENDER" --depth 8.7 -o "$X_PNG"
num depth_1e300 "--depth: '1e300'" "$RENDER" --depth 1e300 -o "$X_PNG"
num depth_empty "--depth" "$RENDER" --depth "" -o "$X_PNG"
num depth_plus_space "--depth" "$RENDER" --depth " 8" -o "$X_PNG"
num zoom_1e400 "--zoom" "$RENDER" --zoom 1e400 -o "$X_PNG"
num zoom_nan "--zoom" "$RENDER" --zoom nan -o "$X_PNG"
num zoom_hex "--zoom" "$RENDER" --zoom 0x1p3 -o "$X_PNG"
num yaw_inf "--yaw" "$RENDER" --yaw inf -o "$X_PNG"
num yaw_past_1e6 "--yaw" "$RENDER" --yaw 1e7 -o "$X_PNG"
num pitch_junk "--pitch" "$RENDER" --pitch 10deg -o "$X_PNG"
num sheet_huge "--sheet" "$RENDER" --sheet 1000000000000 -o "$X_PNG"
num fov_nan "--fov" "$RENDER" --perspective --fov nan -o "$X_PNG"
num fov_1e400 "--fov" "$RENDER" --perspective --fov 1e400 -o "$X_PNG"
num fov_zero "--fov" "$RENDER" --perspective --fov 0 -o "$X_PNG"
num fov_past_120 "--fov" "$RENDER" --perspective --fov 120.001 -o "$X_PNG"
num perspective_eye_past_128_edges "128 cube edges" "$RENDER" --perspective --zoom 0.0001 -o "$X_PNG"
num eye_nan "--eye" "$RENDER" --eye 0,nan,0 -o "$X_PNG"
num eye_1e400 "--eye" "$RENDER" --eye 0,0,1e400 -o "$X_PNG"
num eye_past_128_edges "the camera holds at most 128" "$RENDER" --eye 0,0,1e6 -o "$X_PNG"
num look_junk "--look" "$RENDER" --eye 0,0,-0.5 --look 10,up -o "$X_PNG"
num budget_zero "--point-budget" "$RENDER" --eye 0,0,-0.5 --point-budget 0 -o "$X_PNG"
num budget_past_2_40 "--point-budget" "$RENDER" --perspective --point-budget 1099511627777 -o "$X_PNG"
refuse 12 budget_with_depth "--depth N does not apply" "$RENDER" --eye 0,0,-0.5 --depth 8 --point-budget 20 -o "$X_PNG"
# --url in perspective with nothing listening: the head never comes, one line, no file.
refuse 12 url_eye_refused "127.0.0.1:1" "$RENDER" --url http://127.0.0.1:1/m.oct --eye 0,0,-0.5 --timeout 5 -o "$X_PNG"
refuse 12 url_path_refused "127.0.0.1:1" "$RENDER" --url http://127.0.0.1:1/m.oct --path "$W/none.json" --frames 2 --timeout 5 -o "$X_PNG"
printf '{"keys": [{"eye": [0, 0, -0.5]}, {"eye": [0, 0.1, -0.6]}]}\n' >"$I2/walk.json"
num frames_huge "--frames" "$RENDER" --path "$I2/walk.json" --frames 1000000000000 -o "$X_PNG"
num frames_too_many_pixels "at most 1073741824" "$RENDER" --path "$I2/walk.json" --frames 3600 --size 4096x4096 -o "$X_PNG"
path_file() {  # path_file NAME EXPECTED JSON: a camera path that must be refused, leaving no frame
  printf '%s\n' "$3" >"$I2/path_$1.json"
  refuse 7 "path_$1" "$2" "$RENDER" --path "$I2/path_$1.json" --frames 4 -o "$X_PNG"
}
path_file bad_json "not valid JSON" '{"keys": [{"eye": [0, 0, -0.5]}'
path_file overflow "not valid JSON" '{"keys": [{"eye": [0, 0, 1e400]}]}'
path_file outside "frame 1" '{"keys": [{"eye": [0, 0, -0.5]}, {"eye": [0, 0, 1000]}]}'
path_file time_nan "expected a number" '{"keys": [{"time": "NaN", "eye": [0, 0, -0.5]}]}'
path_file many_keys "1 to 1000 keys" "{\"keys\": [$(awk 'BEGIN { for (i = 0; i < 1001; i++) printf "{\"eye\": [0, 0, -0.5]},"; }' | sed 's/,$//')]}"
num size_negative "--size" "$RENDER" --size -320x240 -o "$X_PNG"
num size_trailing "--size" "$RENDER" --size 320x240x1 -o "$X_PNG"
num missing_value "--size" "$RENDER" -o "$X_PNG" --size
num colours_fraction "--colours" "$PREPARE" "$IN/good.pcd" -o "$P_OUT" --name m --colours 256.0
num colours_zero "--colours" "$PREPARE" "$IN/good.pcd" -o "$P_OUT" --name m --colours 0
num depths_zero "--depths" "$PREPARE" "$IN/good.pcd" -o "$P_OUT" --name m --depths 0
num depths_range_huge "--depths" "$PREPARE" "$IN/good.pcd" -o "$P_OUT" --name m --depths 1..99999999999
num depths_range_long "--depths: '1..16' is 16 depths, at most 8" "$PREPARE" "$IN/good.pcd" -o "$P_OUT" --name m --depths 1..16
num crop_nan "--crop" "$PREPARE" "$IN/good.pcd" -o "$P_OUT" --name m --crop nan,0,0,1,1,1
num q:fraction_bits_zero "--fraction-bits: 0 is outside" "$TRADEOFF" "$IN/good.pcd" --fraction-bits 0 -o "$T_OUT"
num rounds_float "--rounds" "$TRADEOFF" "$IN/good.pcd" --sweep-views --rounds 1e2 -o "$T_OUT"
num zooms_empty_item "--zooms" "$TRADEOFF" "$IN/good.pcd" --sweep-views --zooms 1,,2 -o "$T_OUT"
[ -n "$VIEW" ] && num view_speed_1e400 "--speed" env -u DISPLAY "$VIEW" --speed 1e400
printf '{"yaw": [0, 1]}\0{"yaw": [0, 300]}\n' >"$I2/nul_junk.json"
refuse 7 scene_nul_junk "a NUL byte at byte 15" "$PREPARE" "$IN/good.pcd" --scene "$I2/nul_junk.json" -o "$P_OUT" --name m
scene 7 scene_duplicate_key "key 'yaw': given twice" '{"yaw": [-30, 30], "yaw": [0, 400]}'
scene 7 scene_depth_fraction "key 'depths': expected a whole number" '{"depths": [6.5]}'
scene 7 scene_depth_u64 "key 'depths'" '{"depths": [18446744073709551617]}'
scene 7 scene_framebuffer_wraps "key 'framebuffer'" '{"framebuffer": [4294967616, 240]}'
scene 7 scene_zoom_nan_string "key 'zoom'" '{"zoom": "nan"}'
scene 7 scene_eye_overflow "(key 'eyes.eye')" '{"eyes": [{"eye": [0, 0, 1e400]}]}'
scene 7 scene_eye_fov_nan "key 'eyes[0].fov'" '{"eyes": [{"eye": [0, 0, 0], "fov": "nan"}]}'
scene 7 scene_path_missing "key 'paths[0]'" '{"paths": ["no_such_walk.json"], "path_frames": 3600}'
scene 7 scene_path_frames_huge "key 'path_frames'" '{"paths": ["x.json"], "path_frames": 1e12}'

# --- 8: model names -------------------------------------------------------------------------
name() {  # name NAME EXPECTED MODEL_NAME
  refuse 8 "$1" "$2" "$PREPARE" "$IN/good.pcd" -o "$P_OUT" --name "$3"
}
name q:keyword_class "is a C++ keyword" class
for keyword in int and_eq co_await char8_t requires alignas; do name "keyword_$keyword" "is a C++ keyword" "$keyword"; done
name trailing_underscore "--name" "model_"
name leading_underscore "--name" "_model"
name double_underscore "--name" "a__b"
name all_capitals "--name" "NULL"
name system_macro "--name" "linux"
name errno "--name" "errno"
name header_name "--name" "stdint"
name leading_digit "--name" "3d"
name space "--name" "a b"
name newline "--name" "$(printf 'a\nb')"
name non_ascii "--name" "caf$(printf '\303\251')"
name empty "--name" ""
name too_long "at most 64" "$(printf 'a%.0s' $(seq 1 65))"

# --- 11: octopoint-tradeoff --depths and --fraction-bits ----------------------------------------
for depths in 0 -1 40 2147483648 99999999999999999999 "" "7,,8" "8,7" "7,7" "6 7" "1e3" \
  "1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17"; do
  q=""
  [ "$depths" = 0 ] && q="q:"
  out "tradeoff_depths"
  refuse 11 "${q}depths_'$depths'" "--depths" "$TRADEOFF" "$IN/good.pcd" --depths "$depths" -o "$OUT/t"
done
for bits in 0 -3 25 "8,8" "12,8" ""; do
  out "tradeoff_bits"
  refuse 11 "fraction_bits_'$bits'" "--fraction-bits" "$TRADEOFF" "$IN/good.pcd" --fraction-bits "$bits" -o "$OUT/t"
done
# A setting the camera refuses for the view is found before the scan is read (here it does not
# exist): nothing is measured, nothing written.
out tradeoff_camera
refuse 11 q:camera_refuses_bits "--fraction-bits 24: the camera refuses" "$TRADEOFF" "$IN/missing.pcd" \
  --depths 6 --fraction-bits 24 --size 4096x4096 -o "$OUT/t"
out tradeoff_camera_existing
refuse 11 camera_refuses_existing "--fraction-bits 24: the camera refuses" "$TRADEOFF" "$IN/good.pcd" \
  --depths 6,7 --fraction-bits 8,24 --zoom 30000 -o "$OUT"
out tradeoff_reference_fifo
mkfifo "$OUT/tradeoff_reference.png"
refuse 11 reference_png_is_fifo "tradeoff_reference.png: exists and is a FIFO" "$TRADEOFF" "$IN/good.pcd" \
  --depths 6 -o "$OUT"

# --- 12: messages ---------------------------------------------------------------------------
scene 12 q:json_overflow_names_key "json_overflow_names_key.json: not valid JSON: number overflow parsing '-1e400' (key 'crop.min')" '{"crop": {"min": [-1e400, 0, 0], "max": [1, 1, 1]}}'
scene 12 json_overflow_in_list "(key 'viewpoints.yaw')" '{"viewpoints": [{"yaw": 1e400, "pitch": 0}]}'
scene 12 json_overflow_names_file "scenes/json_overflow_names_file.json: not valid JSON: number overflow" \
  '{"zoom": [1, 1e400]}'
long_key=$(printf 'k%.0s' $(seq 1 5000))
scene 12 long_key_cut "'kkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkk...': unknown key" "{\"$long_key\": 1}"
printf '%*s' 1000000 '' | tr ' ' '[' >"$I2/deep.json"
refuse 12 deep_nesting "nested deeper than 8 levels" "$PREPARE" "$IN/good.pcd" --scene "$I2/deep.json" -o "$P_OUT" --name m
refuse 12 long_option_value_cut "'aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa...'" "$RENDER" --model "$(printf 'a%.0s' $(seq 1 5000))" -o "$X_PNG"
refuse 12 long_unknown_option_cut "unknown option" "$RENDER" "--$(printf 'a%.0s' $(seq 1 5000))"
refuse 12 name_limit_stated "is 300 characters long, at most 64" "$PREPARE" "$IN/good.pcd" -o "$P_OUT" --name "$(printf 'a%.0s' $(seq 1 300))"
refuse 12 long_path_cut "no such file" "$RENDER" --file "$IN/$(printf 'd/%.0s' $(seq 1 2000))m.oct" -o "$X_PNG"
refuse 12 q:directory_not_missing "is a directory, not a model file" "$RENDER" --file "$IN" -o "$X_PNG"
# A level error names its byte in the file: the first node byte of the first level, set to 0 (an
# inner node without children), sits after the level table, one 12-byte row per level.
levels=$(od -An -tu1 -j6 -N1 "$IN/good.oct" | tr -d ' ')
first_node=$(($(levelTable "$IN/good.oct") + 12 * levels))
patchBytes "$IN/empty_node.oct" "$first_node" '\000'
refuse 12 q:level_error_file_byte "file byte $first_node" "$RENDER" --file "$IN/empty_node.oct" -o "$X_PNG"
