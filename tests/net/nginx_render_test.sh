#!/usr/bin/env bash
# The client against another static server with Range support: Debian's nginx, started here with
# its own configuration, prefix and logs in a temporary folder, on a free port of 127.0.0.1, and
# stopped by its pid. The pictures drawn from it equal those drawn from the file. Exits 77 (skipped)
# when nginx is not installed (scripts/test installs it).
# usage: nginx_render_test.sh PREPARE RENDER SCAN WORKDIR
set -euo pipefail
prepare=$1 render=$2 scan=$3 work=$4
source "$(dirname "$0")/net_script_lib.sh"
nginx=$(command -v nginx || true)
[ -x "${nginx:-/usr/sbin/nginx}" ] || nginx=/usr/sbin/nginx
[ -x "$nginx" ] || { echo "nginx is not installed: skipped"; exit 77; }
rm -rf "$work" && mkdir -p "$work/models" "$work/nginx/tmp"
"$prepare" "$scan" -o "$work/models" --name sphere --depths 4,5,6,7 --chunked >/dev/null
port=$(free_port)
prefix=$work/nginx
cat >"$prefix/nginx.conf" <<CONF
$( [ "$(id -u)" -eq 0 ] && echo "user root;" )
worker_processes 1;
daemon off;
pid $prefix/nginx.pid;
error_log $prefix/error.log;
events { worker_connections 64; }
http {
  access_log off;
  default_type application/octet-stream;
  client_body_temp_path $prefix/tmp/body;
  proxy_temp_path $prefix/tmp/proxy;
  fastcgi_temp_path $prefix/tmp/fastcgi;
  uwsgi_temp_path $prefix/tmp/uwsgi;
  scgi_temp_path $prefix/tmp/scgi;
  server {
    listen 127.0.0.1:$port;
    root $work/models;
  }
}
CONF
"$nginx" -p "$prefix" -c "$prefix/nginx.conf" -e "$prefix/error.log" &
nginx_pid=$!
trap 'stop_pid $nginx_pid' EXIT
wait_for_port "$port"
url="http://127.0.0.1:$port/sphere.oct"
for view in "--yaw 0" "--yaw 30 --pitch -20" "--zoom 4 --yaw 10"; do
  # shellcheck disable=SC2086
  "$render" --file "$work/models/sphere.oct" $view --no-fill -o "$work/file.png" >/dev/null
  # shellcheck disable=SC2086
  "$render" --url "$url" $view --no-fill -o "$work/url.png" >/dev/null || fail "--url failed against nginx: $(cat "$prefix/error.log")"
  cmp -s "$work/file.png" "$work/url.png" || fail "--url (nginx) and --file differ for view '$view'"
done
"$render" --url "$url" --bytes 3000 -o "$work/bytes_a.png" >/dev/null
"$render" --url "$url" --bytes 3000 -o "$work/bytes_b.png" >/dev/null
cmp -s "$work/bytes_a.png" "$work/bytes_b.png" || fail "--bytes 3000 drew two different pictures"
echo "ok: nginx $("$nginx" -v 2>&1 | sed 's|.*/||') on port $port, --url matches --file"
