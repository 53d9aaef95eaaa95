"""The serial acceptance suite (`osdkc device`): passive and active runs
against a flight controller, capture analysis, plots, and the soak benchmark."""
