// Command send prints one frame of each command an onboard computer sends,
// as `NAME HEX` (tests/library_examples.py SENT).
package main

import (
	"encoding/hex"
	"fmt"
	"os"

	osdk "osdk-conformance.local/generated/go/osdk_kaitai"
)

func main() {
	var bundleID [32]byte
	copy(bundleID[:], "0123456789abcdef0123456789abcdef")
	frames := []struct {
		cmd     osdk.Command
		session uint8
		seq     uint16
		value   []byte
	}{
		{osdk.CommandVersionQuery, 2, 1, osdk.EncodeVersionQuery(0)},
		{osdk.CommandActivation, 2, 2, osdk.EncodeActivation(1000001, 2, 0x03016400, bundleID)},
		{osdk.CommandSetFrequency, 2, 3, osdk.EncodeSetFrequency([16]uint8{1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 0, 0})},
		{osdk.CommandControlAuthority, 2, 4, osdk.EncodeControlAuthority(1)},
		{osdk.CommandMovementControl, 0, 0x1234, osdk.EncodeMovementControl(0x4B, 1.0, -2.0, 0.5, 30.0)},
	}
	for _, f := range frames {
		raw, err := osdk.EncodeFrame(f.cmd.CmdSet, f.cmd.CmdID, false, f.session, f.seq, f.value)
		if err != nil { // *osdk.Error: impossible_length or bad_session
			fmt.Fprintln(os.Stderr, "send:", err)
			os.Exit(1)
		}
		fmt.Println(f.cmd.Name, hex.EncodeToString(raw))
	}
}
