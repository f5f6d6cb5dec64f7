# Sourced by the editor's window tests after window_test.sh: how the window's pixels map onto a face
# seen head-on (face 0 as the editor opens, another after F), from three presses in the select tool
# (a press on nothing selects nothing), and back: pixel X Y prints the window pixel of that face's
# point (X, Y), or "off" when a press was on another face. probe_face0 zooms out three wheel
# notches first (the whole face in view), then sets $map; probe_face N probes face N as it is.
probe_face0() { probe_face 0; }

probe_face() {
  face=$1
  xdotool key s
  before=$(grep -c "^press at pixel" "$log" || true)
  for p in "580 400" "700 400" "640 450"; do  # near the middle: inside the smallest face
    xdotool mousemove --window "$window" $p click 1
  done
  await "^press at pixel" $((before + 3))
  map=$(grep "^press at pixel" "$log" | tail -3 | sed 's/[^-0-9. ]/ /g' | tr -s ' ' | tr '\n' ' ')
}

pixel() {
  echo "$map" | awk -v X="$1" -v Y="$2" -v F="$face" '{
    px1=$1; py1=$2; f1=$3; x1=$4; y1=$5; px2=$6; py2=$7; x2=$9; y2=$10; px3=$11; py3=$12; x3=$14; y3=$15;
    if (f1 != F || $8 != F || $13 != F) { print "off"; exit }
    # face = A * (pixel - p1) + face1, A from two columns; solve for the pixel
    a = (x2 - x1) / (px2 - px1); c = (y2 - y1) / (px2 - px1); b = (x3 - x1 - a * (px3 - px1)) / (py3 - py1);
    d = (y3 - y1 - c * (px3 - px1)) / (py3 - py1); det = a * d - b * c;
    dx = X - x1; dy = Y - y1;
    printf "%d %d\n", px1 + (d * dx - b * dy) / det, py1 + (-c * dx + a * dy) / det }'
}

# drag X0 Y0 X1 Y1: the left button from the probed face's point to another, through the middle.
drag() {
  xdotool mousemove --window "$window" $(pixel "$1" "$2") mousedown 1
  xdotool mousemove --window "$window" $(pixel $((($1 + $3) / 2)) $((($2 + $4) / 2)))
  xdotool mousemove --window "$window" $(pixel "$3" "$4") mouseup 1
}

# point X Y: the pointer onto the probed face's point.
point() { xdotool mousemove --window "$window" $(pixel "$1" "$2"); }
