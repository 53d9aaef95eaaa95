"""The reference decoder and encoder (the Construct spec behind `osdkc decode`
and every golden vector's expectation) and the outside worked examples."""
