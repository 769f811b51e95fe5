#!/usr/bin/env bash
# Renders every example program's figure into OUT_DIR and writes OUT_DIR/index.html, a gallery whose
# captions come from the programs themselves: each example_NAME OUT_DIR writes OUT_DIR/NAME.png and prints
# one caption line on stdout. Figures are grouped by the course note their caption cites (its author),
# the project's own scenes last (docs/gallery.md).
set -euo pipefail
build_dir=${1:?usage: render_examples.sh BUILD_DIR OUT_DIR}
out_dir=${2:?usage: render_examples.sh BUILD_DIR OUT_DIR}
mkdir -p "$out_dir"

# A caption cites its course note by author; the group key orders the notes as the course does.
note_key() {
  case "$(grep -oE 'Umetani|Ince|Dill|Gallivan|U\. of Toronto' <<<"$1" | head -n 1)" in
    Umetani) echo "1" ;;
    Ince) echo "2" ;;
    Dill) echo "3" ;;
    Gallivan) echo "4" ;;
    "U. of Toronto") echo "5" ;;
    *) echo "9" ;;
  esac
}
note_title() {
  case "$1" in
    1) echo "After Umetani, <i>Parametric Curve</i>" ;;
    2) echo "After Ince, <i>Curves</i>" ;;
    3) echo "After Dill, <i>Introduction to Parametric Curves</i>" ;;
    4) echo "After Gallivan, <i>Parametric Curves</i>" ;;
    5) echo "After <i>Parametric Curves</i> (University of Toronto)" ;;
    *) echo "Scenes of curvescan's own" ;;
  esac
}

html_escape() { sed -e 's/&/\&amp;/g' -e 's/</\&lt;/g' -e 's/>/\&gt;/g'; }

entries=""  # one line per figure: "<group key>\t<name>\t<caption>"
count=0
for program in "$build_dir"/examples/example_*; do
  [ -x "$program" ] || continue
  name=$(basename "$program"); name=${name#example_}
  if ! caption=$("$program" "$out_dir" | head -n 1); then
    echo "render_examples.sh: $name failed (see the error above)" >&2
    exit 1
  fi
  group=$(note_key "$caption")
  entries+="$group"$'\t'"$name"$'\t'"$caption"$'\n'
  count=$((count + 1))
done
if [ "$count" -eq 0 ]; then
  echo "render_examples.sh: no example programs in $build_dir/examples (build them first)" >&2
  exit 1
fi

sections=""
current=""
while IFS=$'\t' read -r group name caption; do
  [ -n "$name" ] || continue
  if [ "$group" != "$current" ]; then
    [ -n "$current" ] && sections+="</main>"$'\n'
    title=$(note_title "$group")
    sections+="<h2>$title</h2><main>"$'\n'
    current=$group
  fi
  caption_html=$(html_escape <<<"$caption")
  sections+="<figure><a href=\"$name.png\"><img src=\"$name.png\" alt=\"$name\"></a><figcaption><b>$name</b> — $caption_html</figcaption></figure>"$'\n'
done < <(sort -t $'\t' -k1,1 -k2,2 <<<"$entries")
sections+="</main>"

cat > "$out_dir/index.html" <<HTML
<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>curvescan gallery</title>
<style>
body { font-family: sans-serif; margin: 2em; background: #fafafa; }
main { display: grid; grid-template-columns: repeat(auto-fill, minmax(460px, 1fr)); gap: 1.5em; }
figure { margin: 0; background: white; padding: 0.8em; border: 1px solid #ddd; }
img { width: 100%; height: auto; image-rendering: auto; }
figcaption { font-size: 0.9em; color: #333; margin-top: 0.5em; }
h2 { margin-top: 1.6em; font-weight: normal; }
</style></head>
<body><h1>curvescan gallery</h1>
<p>$count figures rendered by curvescan: the illustrations of five course notes on parametric curves
(Umetani; Ince; Dill; Gallivan; University of Toronto) redrawn with exact curves, and scenes of the project's own. See docs/gallery.md.</p>
$sections
</body></html>
HTML
echo "Rendered $count figures into $out_dir (open $out_dir/index.html)"
