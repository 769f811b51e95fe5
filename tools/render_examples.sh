#!/usr/bin/env bash
# Renders every example program's figure into OUT_DIR and writes OUT_DIR/index.html, a gallery whose
# captions come from the programs themselves: each example_NAME OUT_DIR writes OUT_DIR/NAME.png and prints
# one caption line on stdout.
set -euo pipefail
build_dir=${1:?usage: render_examples.sh BUILD_DIR OUT_DIR}
out_dir=${2:?usage: render_examples.sh BUILD_DIR OUT_DIR}
mkdir -p "$out_dir"

html_escape() { sed -e 's/&/\&amp;/g' -e 's/</\&lt;/g' -e 's/>/\&gt;/g'; }

figures=""
count=0
for program in "$build_dir"/examples/example_*; do
  [ -x "$program" ] || continue
  name=$(basename "$program"); name=${name#example_}
  caption=$("$program" "$out_dir" | head -n 1 | html_escape)
  figures+="<figure><a href=\"$name.png\"><img src=\"$name.png\" alt=\"$name\"></a><figcaption><b>$name</b> — $caption</figcaption></figure>"$'\n'
  count=$((count + 1))
done

cat > "$out_dir/index.html" <<HTML
<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>curvescan gallery</title>
<style>
body { font-family: sans-serif; margin: 2em; background: #fafafa; }
main { display: grid; grid-template-columns: repeat(auto-fill, minmax(340px, 1fr)); gap: 1.5em; }
figure { margin: 0; background: white; padding: 0.8em; border: 1px solid #ddd; }
img { width: 100%; height: auto; image-rendering: auto; }
figcaption { font-size: 0.9em; color: #333; margin-top: 0.5em; }
</style></head>
<body><h1>curvescan gallery</h1><p>$count figures rendered by curvescan.</p><main>
$figures</main></body></html>
HTML
echo "Rendered $count figures into $out_dir (open $out_dir/index.html)"
