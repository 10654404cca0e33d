#!/bin/sh
# run_mesa_eval.sh BIN_DIR: the evaluated values of Mesa and of libglfixed,
# compared line by line; exit status 1 on any difference.
set -u
bin=$1
"$bin/mesa_eval_feedback" > "$bin/mesa_eval.txt" || { echo "mesa_eval_feedback failed"; exit 2; }
"$bin/glfixed_eval_values" > "$bin/glfixed_eval.txt" || { echo "glfixed_eval_values failed"; exit 2; }
lines=$(wc -l < "$bin/mesa_eval.txt")
if [ "$lines" -eq 0 ]; then echo "Mesa gave no feedback"; exit 2; fi
differ=$(diff "$bin/mesa_eval.txt" "$bin/glfixed_eval.txt" | grep -c '^[<>]')
echo "evaluated vertices: $lines, differing from Mesa: $differ"
if [ "$differ" -ne 0 ]; then
  diff "$bin/mesa_eval.txt" "$bin/glfixed_eval.txt" | head -20
  exit 1
fi
exit 0
