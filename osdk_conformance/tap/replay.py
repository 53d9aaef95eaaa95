"""A recorded session judged again: the capture's records fed to a judge in
the order they were recorded, then every check (`osdkc tap --replay`, and
`judge_capture` of the Python API)."""
from __future__ import annotations

from dataclasses import dataclass

from osdk_conformance.core.capture import RX, open_capture
from osdk_conformance.device.analysis import Analyzer
from osdk_conformance.harness.report import Result
from osdk_conformance.tap.checks import TapOptions, tap_results
from osdk_conformance.tap.judge import REORDER_S, HostJudge


@dataclass
class Judged:
    results: list[Result]
    judge: HostJudge
    records: int
    partial_tail: int      # bytes of an incomplete last block (the recorder was killed)
    comment: dict          # what the capture says it is


def judge_capture(path, opts: TapOptions, key: bytes | None = None) -> Judged:
    """Every check on the capture at `path`. OSError when it cannot be read,
    CaptureError when it is not a capture or is damaged."""
    an = Analyzer(opts.device.profile, key, opts.device.expect_rates, ack_reorder_s=REORDER_S)
    with open_capture(path) as capf:   # block by block: memory does not grow with the file
        # a passive tap's capture holds two lines read through two adapters, judged as it judged them live
        judge = HostJudge(an, opts.device.profile, two_lines=capf.comment.get("mode") == "passive")
        for rec in capf:
            (judge.feed_rx if rec.direction == RX else judge.feed_tx)(rec.t, rec.data)
    judge.finish()
    if an.first_t is not None and an.last_t is not None:
        opts.device.duration = an.last_t - an.first_t
    return Judged(tap_results(judge, opts, None), judge, capf.count, capf.partial_tail, dict(capf.comment))
