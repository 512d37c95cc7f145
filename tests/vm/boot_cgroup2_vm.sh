#!/usr/bin/env bash
# A throwaway Linux VM with pure cgroup v2 (as Debian 12, Ubuntu 22.04+ and Fedora mount it), to test what a
# machine mounting cgroup v1 cannot show: boots the distribution's own kernel under qemu, software emulation
# (TCG: /dev/kvm may be missing or unusable in a CI container), with this machine's whole filesystem shared
# read-only over 9p as the guest's root. cgroup2 is mounted with memory, pids and cpu on for the root's
# children, and GUEST_SCRIPT runs as root (/run a writable tmpfs, TMPDIR=/run/tmp, HOME=/run/home).
#
#   usage: boot_cgroup2_vm.sh [--timeout SECONDS] GUEST_SCRIPT [ARG...]
#
# Exit 0 when the guest script exited 0 having printed a line VM-OK; 77 (skipped) when qemu cannot run here
# (its packages missing and not installable, no kernel to boot); 1 otherwise. Installs, as root through
# apt-get, what it lacks: qemu-system-x86 linux-image-amd64 busybox-static cpio.
set -euo pipefail
self=$(realpath "$0")

if [ "${1:-}" = --stage2 ]; then
  # ---- in the guest, after switch_root: bash is PID 1 on the host's filesystem ----------------------------
  shift
  mount -t tmpfs -o size=1g,mode=755 tmpfs /run
  mkdir -m 1777 /run/tmp && mkdir -m 755 /run/home
  mount -t cgroup2 cgroup2 /sys/fs/cgroup
  echo "+memory +pids +cpu" > /sys/fs/cgroup/cgroup.subtree_control
  export PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin TMPDIR=/run/tmp HOME=/run/home LANG=C.UTF-8
  cd /run/tmp
  echo "VM: $(uname -r), cgroup2 controllers: $(cat /sys/fs/cgroup/cgroup.subtree_control), $(nproc) CPUs"
  status=0
  bash "$@" || status=$?
  echo "VM-EXIT $status"
  mkfifo /run/wait
  sync
  echo o > /proc/sysrq-trigger  # power off at once (were PID 1 to return, the kernel's panic: -no-reboot)
  read -r -t 60 <> /run/wait || true  # a builtin: the host's files go away while the guest powers off
  exit 0
fi

timeout_s=900
if [ "${1:-}" = --timeout ]; then timeout_s=$2; shift 2; fi
[ $# -ge 1 ] || { echo "usage: $0 [--timeout SECONDS] GUEST_SCRIPT [ARG...]" >&2; exit 2; }
guest=$(realpath "$1"); shift
skip() { echo "boot_cgroup2_vm.sh: skipped: $*"; exit 77; }

# ---- what the host needs ------------------------------------------------------------------------------------
static_busybox() {  # a static busybox (the initramfs has no libraries); Debian's busybox-static is one
  local b; b=$(command -v busybox 2>/dev/null) || return 1
  ! ldd "$b" > /dev/null 2>&1 && echo "$b"
}
newest_kernel() {  # the newest /boot/vmlinuz-VERSION whose modules are installed
  local k
  for k in $(ls /boot/vmlinuz-* 2>/dev/null | sort -V -r); do
    [ -f "/lib/modules/${k#/boot/vmlinuz-}/modules.dep" ] && { echo "$k"; return 0; }
  done
  return 1
}
ready() { command -v qemu-system-x86_64 > /dev/null && command -v cpio > /dev/null && static_busybox > /dev/null && newest_kernel > /dev/null; }
if ! ready; then
  [ "$(id -u)" = 0 ] && command -v apt-get > /dev/null ||
    skip "needs qemu-system-x86 linux-image-amd64 busybox-static cpio (install them as root)"
  echo "boot_cgroup2_vm.sh: installing qemu-system-x86 linux-image-amd64 busybox-static cpio"
  { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
      qemu-system-x86 linux-image-amd64 busybox-static cpio > /dev/null; } || skip "apt-get could not install them"
  ready || skip "still no qemu, static busybox, cpio or kernel with its modules after installing"
fi
kernel=$(newest_kernel); version=${kernel#/boot/vmlinuz-}
[ -r "$kernel" ] || skip "$kernel is not readable by this user"
qemu-system-x86_64 -version > /dev/null 2>&1 || skip "qemu-system-x86_64 does not start"

# ---- the initramfs: busybox, the modules a 9p root needs (in dependency order), an init -------------------
work=$(mktemp -d "${TMPDIR:-/tmp}/raycam-vm.XXXXXX")
trap 'rm -rf "$work"' EXIT
root=$work/initramfs
mkdir -p "$root"/{bin,dev,proc,sys,newroot,modules}
cp "$(static_busybox)" "$root/bin/busybox"
count=0
# modprobe prints each module's dependencies first ("insmod PATH"), or "builtin NAME" for those in the kernel.
while read -r word path _; do
  [ "$word" = insmod ] || continue
  count=$((count + 1))
  out=$(printf '%s/modules/%02d.ko' "$root" "$count")
  case "$path" in
    *.xz) xz -dc "$path" > "$out" ;;
    *.zst) zstd -qdc "$path" > "$out" ;;
    *.gz) gzip -dc "$path" > "$out" ;;
    *) cp "$path" "$out" ;;
  esac
done < <(modprobe -a -S "$version" --show-depends virtio_pci 9pnet_virtio 9p | awk '!seen[$0]++')
stage2=$(printf '%q ' "$self" --stage2 "$guest" "$@")
cat > "$root/init" <<EOF
#!/bin/busybox sh
export PATH=/bin
/bin/busybox mount -t proc proc /proc
/bin/busybox mount -t sysfs sysfs /sys
/bin/busybox mount -t devtmpfs devtmpfs /dev
for m in /modules/*.ko; do [ -e "\$m" ] && /bin/busybox insmod "\$m"; done
if ! /bin/busybox mount -t 9p -o trans=virtio,version=9p2000.L,ro,cache=loose hostroot /newroot; then
  echo "VM: the host's filesystem cannot be mounted"; /bin/busybox poweroff -f
fi
for m in proc sys dev; do /bin/busybox mount --move /\$m /newroot/\$m; done
exec /bin/busybox switch_root /newroot /bin/bash -c "exec $stage2"
EOF
chmod 755 "$root/init" "$root/bin/busybox"
(cd "$root" && find . -print0 | cpio --null -o -H newc --quiet | gzip -1) > "$work/initramfs.gz"

# ---- boot -------------------------------------------------------------------------------------------------------
echo "boot_cgroup2_vm.sh: booting $version under qemu (TCG, 2 CPUs, 2 GiB), at most ${timeout_s}s"
started=$(date +%s)
# The console streams (a slow guest shows where it is); qemu's status is kept aside from the pipe's.
{
  timeout -k 10 "$timeout_s" qemu-system-x86_64 -accel tcg -cpu max -smp 2 -m 2048 \
    -nographic -no-reboot -kernel "$kernel" -initrd "$work/initramfs.gz" \
    -append "console=ttyS0 panic=-1 loglevel=3 quiet" \
    -virtfs local,path=/,mount_tag=hostroot,security_model=none,readonly=on,multidevs=remap < /dev/null 2>&1
  echo $? > "$work/status"
} | sed -u -e 's/\r$//' -e 's/\x1b\[[0-9;?]*[A-Za-z]//g' -e 's/\x1bc//g' | grep -av --line-buffered -e '^[[:space:]]*$' -e 'SeaBIOS' -e 'iPXE' -e 'Booting from' |
  tee "$work/console.txt" || true
status=$(cat "$work/status")
echo "boot_cgroup2_vm.sh: the VM ran $(($(date +%s) - started))s"
[ "$status" = 124 ] && { echo "boot_cgroup2_vm.sh: stopped after ${timeout_s}s"; exit 1; }
grep -aqx 'VM-EXIT 0' "$work/console.txt" && grep -aqx 'VM-OK' "$work/console.txt" && exit 0
echo "boot_cgroup2_vm.sh: the guest script did not pass (no VM-OK, or a non-zero VM-EXIT)"
exit 1
