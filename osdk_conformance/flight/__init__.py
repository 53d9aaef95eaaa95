"""Flight data for people: the broadcasts of a capture as typed columns,
typed records, tables and plots.

The conformance value model (docs/VALUE-MODEL.md) says exactly what a frame
held, in JSON; it is what the vectors pin and what `osdkc decode` prints.
This package is the other shape, for analysing a flight: one column per
leaf of the profile's broadcast layout, filled by the native decoder with
no Python object per value (columns.py), the capture time of each frame
and the flight controller's own time stamp in seconds beside it; records
with attribute access and Python types over those columns (records.py);
Arrow tables, CSV, Parquet and JSON lines (tables.py); and the same small
multiples the acceptance report draws (plot.py).

Both shapes come from the same decoder, and the tests hold them to each
other on every vector and on the bench corpora, floats bit for bit.
"""
