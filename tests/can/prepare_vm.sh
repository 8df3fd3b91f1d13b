#!/usr/bin/env bash
# Prepares the small Linux VM the vcan integration tests boot when the host
# kernel has no SocketCAN (see docs/can.md): Debian's generic kernel image
# (fetched with `apt-get download`, never installed on the host), its CAN,
# vcan, virtio and 9p modules, busybox-static and an /init. Everything is
# cached in OUT_DIR (in the build tree); a second run only checks the cache.
#
# usage: prepare_vm.sh OUT_DIR
# Leaves OUT_DIR/vmlinux (uncompressed, booted directly through PVH) and
# OUT_DIR/initrd.gz.
set -euo pipefail

out=${1:?usage: prepare_vm.sh OUT_DIR}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
out=$(cd "$out" && pwd)

if [ -s "$out/vmlinux" ] && [ -s "$out/initrd.gz" ] && [ "$out/initrd.gz" -nt "$here/vm_init.sh" ]; then
  echo "prepare_vm: cached in $out"
  exit 0
fi

for tool in qemu-system-x86_64 apt-get apt-cache dpkg-deb xz gzip; do
  command -v "$tool" >/dev/null || { echo "prepare_vm: '$tool' not found (run tools/setup.sh)" >&2; exit 1; }
done
# The VM has no libc of its own: busybox must be the static build.
busybox=/bin/busybox
if [ ! -x "$busybox" ] || ldd "$busybox" >/dev/null 2>&1; then
  echo "prepare_vm: $busybox is missing or not static (install busybox-static: tools/setup.sh)" >&2
  exit 1
fi

# The generic kernel the meta-package points at (the cloud kernel has no CAN).
kpkg=$(apt-cache depends linux-image-amd64 2>/dev/null | awk '/Depends: linux-image-[0-9]/ {print $2; exit}')
[ -n "$kpkg" ] || { echo "prepare_vm: cannot resolve linux-image-amd64's kernel package (apt-get update?)" >&2; exit 1; }
deb=$(ls "$out"/"$kpkg"_*.deb 2>/dev/null | head -1 || true)
if [ -z "$deb" ]; then
  echo "prepare_vm: apt-get download $kpkg"
  (cd "$out" && apt-get download -q "$kpkg" 2>&1 | grep -v "unsandboxed" || true)
  deb=$(ls "$out"/"$kpkg"_*.deb 2>/dev/null | head -1 || true)
  [ -n "$deb" ] || { echo "prepare_vm: apt-get download $kpkg failed" >&2; exit 1; }
fi

work="$out/extract"
rm -rf "$work" && mkdir -p "$work"
modules=(
  drivers/virtio/virtio_ring.ko drivers/virtio/virtio.ko drivers/virtio/virtio_pci_modern_dev.ko
  drivers/virtio/virtio_pci_legacy_dev.ko drivers/virtio/virtio_pci.ko
  fs/netfs/netfs.ko fs/fscache/fscache.ko net/9p/9pnet.ko net/9p/9pnet_virtio.ko fs/9p/9p.ko
  net/can/can.ko net/can/can-raw.ko drivers/net/can/dev/can-dev.ko drivers/net/can/vcan.ko
)
patterns=('./boot/vmlinuz-*')
for m in "${modules[@]}"; do patterns+=("./lib/modules/*/kernel/$m"); done
dpkg-deb --fsys-tarfile "$deb" | tar -x -C "$work" --wildcards "${patterns[@]}"

# vmlinuz is a bzImage holding an xz stream; the uncompressed ELF boots ~3x
# faster (PVH). xz exits 1 on the trailing bytes after the stream: ignore it.
vmlinuz=$(ls "$work"/boot/vmlinuz-*)
offset=$(LC_ALL=C grep -obUaP '\xFD7zXZ\x00' "$vmlinuz" | head -1 | cut -d: -f1)
[ -n "$offset" ] || { echo "prepare_vm: no xz stream in $vmlinuz" >&2; exit 1; }
tail -c +$((offset + 1)) "$vmlinuz" | xz -dc > "$out/vmlinux.tmp" 2>/dev/null || true
head -c 4 "$out/vmlinux.tmp" | grep -q ELF || { echo "prepare_vm: decompressed kernel is not an ELF" >&2; exit 1; }
mv "$out/vmlinux.tmp" "$out/vmlinux"

root="$work/initramfs"
mkdir -p "$root"/{bin,sbin,proc,sys,dev,host,tmp,modules}
cp "$busybox" "$root/bin/busybox"
for m in "${modules[@]}"; do cp "$work"/lib/modules/*/kernel/"$m" "$root/modules/"; done
printf '%s\n' "${modules[@]##*/}" > "$root/modules/order"
cp "$here/vm_init.sh" "$root/init"
chmod +x "$root/init"
(cd "$root" && find . | "$busybox" cpio -o -H newc 2>/dev/null | gzip -1 > "$out/initrd.gz.tmp")
mv "$out/initrd.gz.tmp" "$out/initrd.gz"
rm -rf "$work"
echo "prepare_vm: kernel $kpkg and initramfs ready in $out"
