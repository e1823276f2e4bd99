#!/bin/sh
# Start the lab, let it run, photograph the screen, then close it. Exit code 0 means it
# was still running when closed; anything else is a crash or an early exit. The X server
# accepts any local client (-ac), so a program in the Debian root can use it too, and
# does not reset when its last client leaves (-noreset: a lab that asks the desktop's
# size before opening its window connects twice, and a resetting server refuses the
# second connection, which a real desktop never does). setsid puts the program (and, in
# the root, the commands around it) in a group of its own.
# Usage (under xvfb-run, from the checkout): runner.sh INSIDE BUILD SECONDS SHOT LOG MOUSE_AT
inside=$1 build=$2 seconds=$3 shot=$4 log=$5 mouse_at=$6
setsid $inside env DISPLAY="$DISPLAY" \
    sh -c "cd \"$build/course_lab_run\" && exec ../course_lab" >"$log" 2>&1 & lab_pid=$!
if [ -n "$mouse_at" ]; then
    sleep 2
    xdotool mousemove $mouse_at mousedown 1
    sleep $((seconds - 2))
else
    sleep "$seconds"
fi
kill -0 "$lab_pid" 2>/dev/null || { wait "$lab_pid"; echo "exited early with code $? (output: $log)" >&2; exit 1; }
ffmpeg -loglevel error -f x11grab -draw_mouse 0 -video_size 1920x1920 -i "$DISPLAY" -frames:v 1 "$shot"
kill -- "-$lab_pid"; wait "$lab_pid" 2>/dev/null; exit 0
