package main

import "fmt"

// CRC is a table-driven CRC for one parameter block of the tables. As in
// the SDK (and osdk_conformance/core/crc.py), Init is the register's start value
// in the register's own shift direction: it is never reflected.
type CRC struct {
	p     CRCParams
	mask  uint64
	table [256]uint64
}

func reflectBits(v uint64, width int) uint64 {
	var out uint64
	for i := 0; i < width; i++ {
		out = out<<1 | v&1
		v >>= 1
	}
	return out
}

func NewCRC(p CRCParams) (*CRC, error) {
	if p.Width < 8 || p.Width > 64 || p.Width%8 != 0 {
		return nil, fmt.Errorf("CRC width %d: only whole bytes of 8 to 64 bits", p.Width)
	}
	c := &CRC{p: p, mask: ^uint64(0) >> (64 - p.Width)}
	if p.ReflectIn {
		poly := reflectBits(p.Poly, p.Width)
		for b := range c.table {
			reg := uint64(b)
			for i := 0; i < 8; i++ {
				if reg&1 != 0 {
					reg = reg>>1 ^ poly
				} else {
					reg >>= 1
				}
			}
			c.table[b] = reg
		}
	} else {
		top := uint64(1) << (p.Width - 1)
		for b := range c.table {
			reg := uint64(b) << (p.Width - 8)
			for i := 0; i < 8; i++ {
				if reg&top != 0 {
					reg = (reg<<1 ^ p.Poly) & c.mask
				} else {
					reg = reg << 1 & c.mask
				}
			}
			c.table[b] = reg
		}
	}
	return c, nil
}

func (c *CRC) Sum(data []byte) uint64 {
	reg := c.p.Init & c.mask
	if c.p.ReflectIn {
		for _, b := range data {
			reg = reg>>8 ^ c.table[byte(reg)^b]
		}
	} else {
		shift := c.p.Width - 8
		for _, b := range data {
			reg = (reg<<8)&c.mask ^ c.table[byte(reg>>shift)^b]
		}
	}
	if c.p.ReflectOut != c.p.ReflectIn {
		reg = reflectBits(reg, c.p.Width)
	}
	return reg ^ c.p.XorOut
}
