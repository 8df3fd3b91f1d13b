#!/bin/busybox sh
# /init of the vcan test VM: load the CAN (and 9p) modules, create vcan0 with
# the CAN FD MTU, mount the host's root read-only over 9p at /host, run one
# test case inside it (chroot, so the host's own binaries and libraries run
# unchanged) and print a marker the host reads from the serial console.
# Kernel command-line words X=Y arrive here as environment variables:
#   IG_CASE     the case name passed to the test program
#   IG_CMD      the test program (absolute host path)
#   IG_WORKDIR  working directory (absolute host path)
/bin/busybox --install -s /bin
export PATH=/bin
mount -t proc proc /proc
mount -t sysfs sys /sys
mount -t devtmpfs dev /dev
for m in $(cat /modules/order); do
  insmod /modules/$m || echo "vm: insmod $m failed"
done
ip link set lo up
ip link add dev vcan0 type vcan && ip link set vcan0 mtu 72 up || echo "vm: cannot create vcan0"
if ! mount -t 9p -o trans=virtio,version=9p2000.L,ro,cache=loose host /host; then
  echo "IG_VM_RESULT case=$IG_CASE rc=97 (9p mount failed)"
  poweroff -f
fi
mount -t proc proc /host/proc 2>/dev/null
mount -t devtmpfs dev /host/dev 2>/dev/null
mount -t sysfs sys /host/sys 2>/dev/null
# A writable /tmp for the programs; a checkout under the host's /tmp (a CI
# clone in /tmp/...) is bound back into it, or the tmpfs would hide it.
keep=""
case "$IG_WORKDIR" in /tmp/?*) keep=$(echo "$IG_WORKDIR" | cut -d/ -f3) ;; esac
if [ -n "$keep" ]; then
  mkdir -p /hosttmp && mount -o bind /host/tmp /hosttmp 2>/dev/null
fi
mount -t tmpfs tmp /host/tmp 2>/dev/null
if [ -n "$keep" ]; then
  mkdir -p "/host/tmp/$keep" && mount -o bind "/hosttmp/$keep" "/host/tmp/$keep" ||
    echo "vm: cannot bind /tmp/$keep back over the tmpfs"
fi
chroot /host /bin/sh -c "cd '$IG_WORKDIR' && '$IG_CMD' '$IG_CASE'"
rc=$?
echo "IG_VM_RESULT case=$IG_CASE rc=$rc"
poweroff -f
