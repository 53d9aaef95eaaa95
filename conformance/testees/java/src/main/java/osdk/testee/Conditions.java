package osdk.testee;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Evaluates a field's ksy `if` expression (tables: if_expressions) on a
 * parsed object. Needed only where the Java object cannot say whether a
 * field was read: an enum field holds null both when its `if` was false and
 * when the spec has no name for the value read.
 *
 * Covers the part of the Kaitai expression language a field condition in
 * this spec uses: `not`, `and`, `or`, parentheses, comparisons of integers,
 * integer and boolean literals, and paths such as `_parent.is_ack` or
 * `has_mode` read through the generated getters. Anything else is refused
 * loudly rather than guessed.
 */
final class Conditions {
    private static final Map<String, List<String>> TOKENS = new ConcurrentHashMap<>();

    private final List<String> tokens;
    private final Object self;
    private int pos;

    private Conditions(List<String> tokens, Object self) {
        this.tokens = tokens;
        this.self = self;
    }

    static boolean holds(Object self, String expr) {
        Conditions c = new Conditions(TOKENS.computeIfAbsent(expr, Conditions::tokenize), self);
        Object v = c.or();
        if (c.pos != c.tokens.size()) {
            throw c.unsupported(expr);
        }
        if (!(v instanceof Boolean)) {
            throw new IllegalStateException("condition '" + expr + "' is not a boolean");
        }
        return (Boolean) v;
    }

    private Object or() {
        Object v = and();
        while (accept("or")) {
            boolean rhs = bool(and());
            v = bool(v) || rhs;
        }
        return v;
    }

    private Object and() {
        Object v = not();
        while (accept("and")) {
            boolean rhs = bool(not());
            v = bool(v) && rhs;
        }
        return v;
    }

    private Object not() {
        if (accept("not")) {
            return !bool(not());
        }
        return comparison();
    }

    private Object comparison() {
        Object left = primary();
        if (pos < tokens.size()) {
            String op = tokens.get(pos);
            if (op.equals("==") || op.equals("!=") || op.equals("<") || op.equals("<=") || op.equals(">")
                    || op.equals(">=")) {
                pos++;
                Object right = primary();
                if (left instanceof Boolean && right instanceof Boolean && (op.equals("==") || op.equals("!="))) {
                    return op.equals("==") == left.equals(right);
                }
                long a = number(left);
                long b = number(right);
                switch (op) {
                    case "==": return a == b;
                    case "!=": return a != b;
                    case "<": return a < b;
                    case "<=": return a <= b;
                    case ">": return a > b;
                    default: return a >= b;
                }
            }
        }
        return left;
    }

    private Object primary() {
        if (pos >= tokens.size()) {
            throw new IllegalStateException("condition ends early");
        }
        String t = tokens.get(pos++);
        if (t.equals("(")) {
            Object v = or();
            if (!accept(")")) {
                throw new IllegalStateException("unbalanced parentheses in a condition");
            }
            return v;
        }
        if (t.equals("true") || t.equals("false")) {
            return Boolean.valueOf(t);
        }
        if (Character.isDigit(t.charAt(0))) {
            return t.startsWith("0x") ? Long.parseLong(t.substring(2), 16) : Long.parseLong(t);
        }
        if (!isIdentifier(t)) {
            throw new IllegalStateException("unsupported token '" + t + "' in a condition");
        }
        Object v = Accessors.get(self, Tables.lowerCamel(t));
        while (accept(".")) {
            String name = tokens.get(pos++);
            if (v == null) {
                throw new IllegalStateException("condition path through null at " + name);
            }
            v = Accessors.get(v, Tables.lowerCamel(name));
        }
        return v;
    }

    private boolean accept(String t) {
        if (pos < tokens.size() && tokens.get(pos).equals(t)) {
            pos++;
            return true;
        }
        return false;
    }

    private static boolean bool(Object v) {
        if (!(v instanceof Boolean)) {
            throw new IllegalStateException("not a boolean in a condition: " + v);
        }
        return (Boolean) v;
    }

    private static long number(Object v) {
        if (!(v instanceof Number)) {
            throw new IllegalStateException("not an integer in a condition: " + v);
        }
        return ((Number) v).longValue();
    }

    private static boolean isIdentifier(String t) {
        return Character.isLetter(t.charAt(0)) || t.charAt(0) == '_';
    }

    private IllegalStateException unsupported(String expr) {
        return new IllegalStateException("unsupported condition '" + expr + "'");
    }

    private static List<String> tokenize(String expr) {
        List<String> out = new ArrayList<>();
        int i = 0;
        while (i < expr.length()) {
            char c = expr.charAt(i);
            if (Character.isWhitespace(c)) {
                i++;
            } else if (Character.isLetterOrDigit(c) || c == '_') {
                int j = i;
                while (j < expr.length() && (Character.isLetterOrDigit(expr.charAt(j)) || expr.charAt(j) == '_')) {
                    j++;
                }
                out.add(expr.substring(i, j));
                i = j;
            } else if ("<>!=".indexOf(c) >= 0 && i + 1 < expr.length() && expr.charAt(i + 1) == '=') {
                out.add(expr.substring(i, i + 2));
                i += 2;
            } else if ("().<>".indexOf(c) >= 0) {
                out.add(String.valueOf(c));
                i++;
            } else {
                throw new IllegalStateException("unsupported character '" + c + "' in condition '" + expr + "'");
            }
        }
        return out;
    }
}
