package osdk.testee;

/** The input was rejected with an error class of docs/VALUE-MODEL.md. */
final class Rejection extends Exception {
    private static final long serialVersionUID = 1L;

    final String cls;
    final String detail;

    Rejection(String cls, String detail) {
        super(cls + ": " + detail, null, false, false);
        this.cls = cls;
        this.detail = detail;
    }
}
