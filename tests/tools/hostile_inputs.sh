#!/usr/bin/env bash
# hostile_inputs.sh BIN_DIR — every tool on a folder of hostile inputs (issue 33): files nested
# 300 000 deep, megabytes of '[', names that are not UTF-8, pipes where files belong, images
# that declare gigapixels, sparse 3 GB buffers, maps with more cells than a map may hold,
# outputs that are inputs, symbolic links and read-only targets, values at the edges of their
# ranges. The files are generated here, at test time (nothing big is committed).
#
# Each run has a timeout and a memory limit (ulimit -v; not under ASan, which reserves
# terabytes of address space) and must end by exiting 0 or 1 — 1 with a message on stderr —
# never by a signal or the timeout. Some runs check more (a file left untouched, a message).
# Needs bash, coreutils, gzip and awk only.
set -u
bin="$1"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
dir="$(mktemp -d "${TMPDIR:-/tmp}/ossa-hostile.XXXXXX")"
trap 'chmod -R u+w "$dir" 2>/dev/null; rm -rf "$dir"' EXIT
export OSSA_SOURCE_DIR="$root" SDL_VIDEODRIVER=offscreen
sanitize="${OSSA_SANITIZE:-0}"
mem_kib=$((4 * 1024 * 1024))   # 4 GiB of address space per run (Mesa's llvmpipe needs some)
seconds=20
# Under the sanitizers everything is slower: the big inputs are made smaller. Leak detection is
# off there (Mesa and Assimp leak on their own, as for the render and app tests); a memory
# error still ends the run by a signal and fails it.
big=1
if [ "$sanitize" = "1" ]; then
  big=0
  export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
fi

failed=0 count=0
fail() { echo "FAIL $*"; failed=$((failed + 1)); }

# run NAME EXPECT CMD...: EXPECT is 0, 1 or "01" (either); stderr is kept in $dir/err.
run() {
  local name="$1" expect="$2"
  shift 2
  count=$((count + 1))
  local rc
  (
    [ "$sanitize" = "1" ] || ulimit -v "$mem_kib"
    exec timeout -s KILL "$seconds" "$@"
  ) >"$dir/out" 2>"$dir/err"
  rc=$?
  if [ "$rc" -gt 1 ]; then
    fail "$name: exit status $rc ($([ "$rc" -ge 124 ] && echo 'a signal or the timeout' || echo 'not 0 or 1')): $(head -c 400 "$dir/err")"
    return
  fi
  if [ "$expect" != "01" ] && [ "$rc" != "$expect" ]; then
    fail "$name: exit status $rc, expected $expect: $(head -c 400 "$dir/err")"
    return
  fi
  if [ "$rc" = 1 ] && [ ! -s "$dir/err" ]; then
    fail "$name: exit status 1 without a message"
    return
  fi
  echo "ok   $name ($rc): $(head -n 1 "$dir/err" | head -c 200)"
}
# must_say NAME TEXT: the last run's stderr or stdout contains TEXT.
must_say() {
  grep -qF -- "$2" "$dir/err" "$dir/out" || fail "$1: expected the message to contain \"$2\", got: $(head -c 300 "$dir/err")"
}
repeat() { head -c "$2" /dev/zero | tr '\0' "$1"; }
level_head='{"format":"ossa.level","version":1,"name":"h","spawn":{"x":1,"y":0.5}'
ground='"colliders":[{"x":-5,"y":-1,"w":20,"h":1}]'
# A PNG signature and header chunk declaring W x H pixels (1-bit grey), padded.
png() {
  local w=$1 h=$2
  printf '\211PNG\r\n\032\n\000\000\000\015IHDR'
  printf "\\$(printf %03o $((w >> 24 & 255)))\\$(printf %03o $((w >> 16 & 255)))\\$(printf %03o $((w >> 8 & 255)))\\$(printf %03o $((w & 255)))"
  printf "\\$(printf %03o $((h >> 24 & 255)))\\$(printf %03o $((h >> 16 & 255)))\\$(printf %03o $((h >> 8 & 255)))\\$(printf %03o $((h & 255)))"
  printf '\001\000\000\000\000'
  head -c 55000 /dev/zero
}
tiny_gltf="$root/tests/fuzz/seeds/mesh/tiny_skin.gltf"
gltf_with() {  # gltf_with TEXT: the tiny skinned glTF with TEXT added before its last brace
  local t
  t="$(cat "$tiny_gltf")"
  printf '%s, %s}' "${t%\}}" "$1"
}

echo "== nesting and size"
depth=300000
{ printf '%s,"notes":' "$level_head"; repeat '[' $depth; repeat ']' $depth; printf ',%s}' "$ground"; } >"$dir/deep.json"
run "ossa-level info: a field nested $depth deep" 1 "$bin/ossa-level" info "$dir/deep.json"
must_say "deep" "nested more than 256"
mb=$((big ? 30 : 4))
repeat '[' $((mb * 1024 * 1024)) >"$dir/brackets.json"
run "ossa-level info: $mb MB of '['" 1 "$bin/ossa-level" info "$dir/brackets.json"
{ printf '{"jsonVersion":"1.5.3","defaultGridSize":16,"levels":[{"identifier":"L","worldX":0,"worldY":0,"fieldInstances":[{"__identifier":"pixels_per_metre","__value":'
  repeat '[' $depth; printf 64; repeat ']' $depth; printf '}],"layerInstances":[]}]}'; } >"$dir/deep.ldtk"
run "ossa-level info: an LDtk field $depth deep" 1 "$bin/ossa-level" info "$dir/deep.ldtk"
{ printf '{"format":"ossa.replay","version":2,"tick_hz":120,"spawn":[1,1],"facing":1,"ticks":[[10,0.5,0,0]],"creature":'
  repeat '[' $depth; repeat ']' $depth; printf '}'; } >"$dir/deep.replay.json"
run "ossa --replay: a creature $depth deep" 1 "$bin/ossa" --headless --no-hud --frames 5 --replay "$dir/deep.replay.json"
{ printf '{"format":"ossa.examples","version":1,"animals":[{"name":"x","spine":['
  repeat '[' $depth; repeat ']' $depth; printf ']}]}'; } >"$dir/deep_dataset.json"
run "ossa-gen --dataset --stats: a spine point $depth deep" 1 "$bin/ossa-gen" --dataset "$dir/deep_dataset.json" --stats
gltf_with "\"extras\": $(repeat '[' 200000)$(repeat ']' 200000)" >"$dir/extras.gltf"
run "ossa-rig guess: glTF extras 200000 deep" 1 "$bin/ossa-rig" guess "$dir/extras.gltf"
must_say "extras" "nested more than 256"
# A chain of 20 000 nodes (node 4 is the chain's root, in the scene).
{ t="$(cat "$tiny_gltf")"; nodes_end='{"name": "mesh", "mesh": 0, "skin": 0}'
  chain="$(awk 'BEGIN { for (i = 0; i < 20000; i++) { printf ", {\"name\": \"n%d\"", i; if (i < 19999) printf ", \"children\": [%d]", i + 5; printf "}" } }')"
  t="${t/"$nodes_end"/"$nodes_end$chain"}"; printf '%s' "${t/'"nodes": [0, 3]'/'"nodes": [0, 3, 4]'}"; } >"$dir/chain.gltf"
run "ossa-rig guess: a node chain 20000 deep" 1 "$bin/ossa-rig" guess "$dir/chain.gltf"
must_say "chain" "more than 1024 nodes deep"
n=$((big ? 1500000 : 200000))   # '{},' x n: the costliest JSON per byte
{ printf '['; awk -v n=$n 'BEGIN { for (i = 1; i < n; i++) printf "{},"; printf "{}" }'; printf ']'; } >"$dir/objects.json"
run "ossa-level info: $n empty objects" 1 "$bin/ossa-level" info "$dir/objects.json"
must_say "objects" "times the text's size"

echo "== file names are bytes"
name="$dir/lev$(printf '\377')el.json"
cp "$root/levels/default.json" "$name"
run "ossa-level info: a name that is not UTF-8" 0 "$bin/ossa-level" info "$name"
run "ossa-level convert: from and to names that are not UTF-8" 0 "$bin/ossa-level" convert "$name" "$dir/out$(printf '\376').json"
run "ossa-sim --json: a level name that is not UTF-8" 0 "$bin/ossa-sim" --example horse --level "$name" --script walk:0.5:1 --json
run "ossa-sweep: a level name that is not UTF-8" 0 "$bin/ossa-sweep" --level "$name" --example horse --script walk:0.5:1 --jobs 1 --json "$dir/sweep.json"
run "ossa --record: a level name that is not UTF-8" 0 "$bin/ossa" --headless --no-hud --frames 20 --level "$name" \
  --record "$dir/r$(printf '\377').replay.json" --state "$dir/state.json"
[ -s "$dir/state.json" ] || fail "ossa --record: no state file written"

echo "== hangs: pipes, huge images, long strips"
mkdir -p "$dir/bg"
png 1 1000000 >"$dir/bg/strip.png"
printf '%s,"background":{"image":"bg/strip.png"},"colliders":[{"x":-5,"y":-1,"w":1000,"h":1}]}' \
  '{"format":"ossa.level","version":1,"name":"h","spawn":{"x":990,"y":0.5}' >"$dir/strip.json"
run "ossa: a 1 x 1000000 background at x = 990" 0 "$bin/ossa" --headless --no-hud --frames 30 --level "$dir/strip.json"
must_say "strip" "images may be at most"
mkfifo "$dir/bg/pipe.png"
printf '%s,"background":{"image":"bg/pipe.png"},%s}' "$level_head" "$ground" >"$dir/pipe_bg.json"
run "ossa: a background image that is a pipe" 0 "$bin/ossa" --headless --no-hud --frames 10 --level "$dir/pipe_bg.json"
must_say "pipe" "is not a regular file"
printf '%s,"background":{"image":"../../../../etc/passwd"},%s}' "$level_head" "$ground" >"$dir/escape_bg.json"
run "ossa: a background image outside the level's folder" 0 "$bin/ossa" --headless --no-hud --frames 5 --level "$dir/escape_bg.json"
must_say "escape" "leaves the level's folder"
t="$(cat "$tiny_gltf")"
printf '%s' "$t" | sed 's#"uri": "data:[^"]*"#"uri": "pipe.bin"#' >"$dir/pipe_buffer.gltf"
mkfifo "$dir/pipe.bin"
run "ossa-rig guess: a glTF buffer that is a pipe" 1 "$bin/ossa-rig" guess "$dir/pipe_buffer.gltf"
printf '%s' "$t" | sed 's#"uri": "data:[^"]*"#"uri": "big.bin"#' >"$dir/big_buffer.gltf"
truncate -s 3G "$dir/big.bin"
run "ossa-rig guess: a 3 GB glTF buffer" 1 "$bin/ossa-rig" guess "$dir/big_buffer.gltf"
must_say "big buffer" "expected at most"
png 16384 16384 >"$dir/skin.png"
gltf_with '"images": [{"uri": "skin.png"}], "textures": [{"source": 0}], "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]' |
  sed 's#"WEIGHTS_0": 2}}#"WEIGHTS_0": 2}, "material": 0}#' >"$dir/textured.gltf"
run "ossa-render --mesh: a 16384 x 16384 texture" 01 "$bin/ossa-render" --mesh "$dir/textured.gltf" --png "$dir/mesh.png"
must_say "texture" "16384 × 16384 pixels"

echo "== work per map"
layer_data="$(head -c $((1024 * 1024 * 4)) /dev/zero | gzip -9 -c | base64 -w0)"
{ printf '{"type":"map","orientation":"orthogonal","width":1024,"height":1024,"tilewidth":32,"tileheight":32,"layers":['
  for i in $(seq 0 39); do
    [ "$i" -gt 0 ] && printf ','
    printf '{"type":"tilelayer","name":"L%d","width":1024,"height":1024,"encoding":"base64","compression":"gzip","data":"%s"}' "$i" "$layer_data"
  done
  printf ']}'; } >"$dir/layers.tmj"
run "ossa-level info: 40 gzip layers of 1 M cells" 1 "$bin/ossa-level" info "$dir/layers.tmj"
must_say "layers" "in all the layers of a map"
boxes=$((big ? 200000 : 20000))
{ printf '%s,"colliders":[' "$level_head"
  awk -v n=$boxes 'BEGIN { for (i = 0; i < n; i++) printf "%s{\"x\":%d,\"y\":-1,\"w\":0.5,\"h\":1}", (i ? "," : ""), (i % 1900) - 950 }'
  printf ']}'; } >"$dir/boxes.json"
run "ossa-level info: $boxes boxes" 0 "$bin/ossa-level" info "$dir/boxes.json"
{ printf '{"type":"map","orientation":"orthogonal","width":10,"height":10,"tilewidth":32,"tileheight":32,"layers":[{"type":"objectgroup","objects":['
  awk -v n=$boxes 'BEGIN { for (i = 0; i < n; i++) printf "%s{\"id\":%d,\"x\":%d,\"y\":0,\"width\":16,\"height\":16}", (i ? "," : ""), i + 1, (i % 1000) * 32 }'
  printf ']}]}'; } >"$dir/objects.tmj"
run "ossa-level info: a Tiled map of $boxes objects" 0 "$bin/ossa-level" info "$dir/objects.tmj"

echo "== outputs never destroy inputs"
cp "$root/tests/level/data/world.ldtk" "$dir/w.ldtk"
sum="$(md5sum <"$dir/w.ldtk")"
run "ossa-level convert w.ldtk#Level_1 w.ldtk" 1 "$bin/ossa-level" convert "$dir/w.ldtk#Level_1" "$dir/w.ldtk"
[ "$(md5sum <"$dir/w.ldtk")" = "$sum" ] || fail "convert overwrote w.ldtk"
cp "$root/tests/level/data/objects.tmj" "$dir/t.tmj"
ln -s t.tmj "$dir/alias.tmj"
run "ossa-level convert t.tmj alias-of-t.tmj" 1 "$bin/ossa-level" convert "$dir/t.tmj" "$dir/alias.tmj"
cp "$tiny_gltf" "$dir/m.gltf"
sum="$(md5sum <"$dir/m.gltf")"
run "ossa-rig guess m.gltf --out m.gltf" 1 "$bin/ossa-rig" guess "$dir/m.gltf" --out "$dir/m.gltf"
[ "$(md5sum <"$dir/m.gltf")" = "$sum" ] || fail "ossa-rig guess overwrote its mesh"
run "ossa-sim --svg over its level" 1 "$bin/ossa-sim" --example horse --level "$dir/boxes.json" --script walk:0.5:1 --svg "$dir/boxes.json"
cp "$root/levels/stairs.json" "$dir/target.json"
ln -s target.json "$dir/link.json"
run "ossa-level convert to a symbolic link" 0 "$bin/ossa-level" convert "$root/levels/default.json" "$dir/link.json"
[ -L "$dir/link.json" ] || fail "the link was replaced by a file"
grep -q '"name": "default"' "$dir/target.json" || fail "the link's target was not written"
cp "$root/levels/stairs.json" "$dir/readonly.json"
chmod 0444 "$dir/readonly.json"
run "ossa-level convert over a read-only file" 1 "$bin/ossa-level" convert "$root/levels/default.json" "$dir/readonly.json"
must_say "read-only" "is read-only"
run "ossa-level convert to \"\"" 1 "$bin/ossa-level" convert "$root/levels/default.json" ""
must_say "empty output" "expected a file name"

echo "== ranges and round trips"
printf '{"type":"map","orientation":"orthogonal","width":10,"height":10,"tilewidth":32,"tileheight":32,"properties":[{"name":"pixels_per_metre","type":"float","value":1}],"layers":[{"type":"objectgroup","objects":[{"id":1,"x":999.9,"y":300,"width":0.1,"height":10},{"id":2,"x":-1000,"y":310,"width":1999.99997,"height":3}]}]}' >"$dir/edge.tmj"
run "ossa-level convert: a box ending at x = 1000 m" 0 "$bin/ossa-level" convert "$dir/edge.tmj" "$dir/edge.json"
run "ossa-level info: the converted edge level loads back" 0 "$bin/ossa-level" info "$dir/edge.json"
printf '%s,"kill_height":3,%s}' "$level_head" "$ground" >"$dir/kill.json"
run "ossa-level info: kill_height above the spawn" 1 "$bin/ossa-level" info "$dir/kill.json"
must_say "kill" "expected below the spawn"
printf '<map orientation="orthogonal" width="2" height="1" tilewidth="32" tileheight="32"><layer name="Collision" width="2" height="1"><data><tile gid="1"/><tile gid="4294967297"/></data></layer></map>' >"$dir/gid.tmx"
run "ossa-level info: a gid past 32 bits" 1 "$bin/ossa-level" info "$dir/gid.tmx"
printf '<map orientation="orthogonal" width="1" height="1" tilewidth="32" tileheight="32"></map>' | iconv -f UTF-8 -t UTF-16 >"$dir/utf16.tmx"
run "ossa-level info: a UTF-16 map" 1 "$bin/ossa-level" info "$dir/utf16.tmx"
must_say "utf16" "UTF-16"
printf '{"format":"ossa.replay","version":2,"tick_hz":120,"spawn":[1000000,0],"facing":1,"ticks":[[10,0.5,0,0]],"creature":{}}' >"$dir/far.replay.json"
run "ossa --replay: a spawn at 1e6 m" 1 "$bin/ossa" --headless --no-hud --replay "$dir/far.replay.json"
run "ossa-sim: thirteen day-long segments at 480 Hz with a trace" 1 "$bin/ossa-sim" --example horse --hz 480 \
  --script "$(printf 'walk:0.5:86400,%.0s' $(seq 12))walk:0.5:86400" --trace "$dir/trace.csv"
must_say "trace" "a trace holds at most"
run "ossa-sim: an SVG pose every tick for 600 s" 1 "$bin/ossa-sim" --example horse --script walk:0.5:600 \
  --svg "$dir/s.svg" --svg-window 0:600:0.001
must_say "svg" "an SVG holds at most"

echo "== characters"
chars="$root/assets/characters"
cp "$chars/humanoid.gltf" "$chars/humanoid.bin" "$chars/humanoid.png" "$dir/"
rig="$(tr -d '\n' <"$chars/humanoid.rig.json")"
printf '%s' "${rig/'"version": 1,'/'"version": 1, "scale": 100,'}" >"$dir/giant.rig.json"
run "ossa-rig check: a character a hundred times too big" 0 "$bin/ossa-rig" check "$dir/giant.rig.json"
must_say "giant" "right? (a mesh in centimetres needs 0.01)"
printf '%s' "$rig" | sed 's#"contact": *\[ *0.19, *0.0 *\]#"contact": [1000000, -1000000]#' >"$dir/contact.rig.json"
grep -q 1000000 "$dir/contact.rig.json" || fail "could not write contact.rig.json"
run "ossa-rig check: a contact point at [1e6, -1e6]" 1 "$bin/ossa-rig" check "$dir/contact.rig.json"
run "ossa-sim --character: a contact point at [1e6, -1e6]" 1 "$bin/ossa-sim" --character "$dir/contact.rig.json" --script walk:0.5:1

echo "hostile inputs: $count runs, $failed failed"
[ "$failed" -eq 0 ]
