// Command receive reads an OPEN protocol byte stream on standard input and
// prints one line per event of the receiver (tests/library_examples.py):
//
//	receive PROFILE < capture.bin
package main

import (
	"bufio"
	"errors"
	"fmt"
	"io"
	"os"

	osdk "osdk-conformance.local/generated/go/osdk_kaitai"
)

func main() {
	if len(os.Args) != 2 {
		fmt.Fprintf(os.Stderr, "usage: receive PROFILE (one of %v) < bytes\n", osdk.Profiles)
		os.Exit(2)
	}
	profile := os.Args[1]
	if _, err := osdk.ProfileOf(profile); err != nil {
		fmt.Fprintln(os.Stderr, "receive:", err)
		os.Exit(2)
	}
	out := bufio.NewWriter(os.Stdout)
	defer out.Flush()
	d := osdk.NewDeframer()
	buf := make([]byte, 4096)
	for {
		n, err := os.Stdin.Read(buf)
		for _, ev := range d.Feed(buf[:n]) {
			show(out, ev, profile)
		}
		if errors.Is(err, io.EOF) {
			break
		}
		if err != nil {
			fmt.Fprintln(os.Stderr, "receive: reading standard input:", err)
			os.Exit(1)
		}
	}
	for _, ev := range d.Finish() {
		show(out, ev, profile)
	}
}

func show(out io.Writer, ev osdk.Event, profile string) {
	switch ev.Kind {
	case osdk.EventGarbage:
		fmt.Fprintf(out, "garbage %d %d\n", ev.Offset, ev.Length)
		return
	case osdk.EventError:
		fmt.Fprintf(out, "error %d %d %s\n", ev.Offset, ev.Length, ev.Err.Class)
		return
	}
	f, err := osdk.DecodeFrame(ev.Raw, profile)
	if err != nil {
		var e *osdk.Error // every rejection is one; Field says where
		if errors.As(err, &e) {
			fmt.Fprintf(out, "error %d %d %s\n", ev.Offset, ev.Length, e.Class)
		}
		return
	}
	switch d := f.Data.(type) {
	case nil:
		fmt.Fprintf(out, "empty %d %d\n", ev.Offset, f.Seq)
	case *osdk.OsdkFrame_FrameData:
		if f.IsAck {
			fmt.Fprintf(out, "ack %d %d\n", ev.Offset, f.Seq)
			return
		}
		fmt.Fprintf(out, "frame %d %d %d %d\n", ev.Offset, f.Seq, d.CmdSet, d.CmdId)
		if bc := osdk.BroadcastOf(f); bc != nil {
			showBroadcast(out, bc, profile)
		}
	}
}

// showBroadcast prints each of the profile's items; an absent one is nil.
func showBroadcast(out io.Writer, bc *osdk.Broadcast, profile string) {
	for _, item := range osdk.BroadcastItems(profile) {
		switch {
		case item == "battery" && bc.Battery() != nil:
			fmt.Fprintf(out, "  battery %d\n", *bc.Battery())
		case item == "time_stamp" && bc.TimeStamp() != nil:
			fmt.Fprintf(out, "  time_stamp %d\n", bc.TimeStamp().Time)
		case bc.Item(item) != nil:
			fmt.Fprintf(out, "  %s present\n", item)
		default:
			fmt.Fprintf(out, "  %s absent\n", item)
		}
	}
}
