package osdk.testee;

/** A request the testee cannot use (answered `bad_request`). */
final class BadRequest extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;

    BadRequest(String message) {
        super(message);
    }
}
