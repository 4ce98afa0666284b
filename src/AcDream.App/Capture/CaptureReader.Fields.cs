using System.Globalization;
using System.Numerics;
using System.Text.Json;
using AcDream.Core.Physics;

namespace AcDream.App.Capture;

// CaptureReader, the fields of a line: requests, answers and the values they are made of, each checked by its path.
internal static partial class CaptureReader
{
    private sealed partial class Line
    {
        private MoverState State(JsonElement parent, string name)
        {
            JsonElement e = Get(parent, "", name);
            Known(e, name, "kind", "physics", "description", "ignoresCreatures");
            return new MoverState(
                Name<MoverKind>(e, name, "kind"), (PhysicsStateFlags)Hex(e, name, "physics"), (ObjectDescriptionFlags)Hex(e, name, "description"),
                Bool(e, name, "ignoresCreatures"));
        }

        private MoveRequest MoveRequest(JsonElement e)
        {
            const string at = "request";
            Known(e, at, "position", "cell", "delta", "step", "options", "mover", "report");
            JsonElement o = Get(e, at, "options");
            const string op = "request.options";
            Known(o, op, "stepDown", "walkableSlope", "sweep", "doorsOnly", "body", "vertical", "footing", "edgeSlide");
            float? stepDown = OptionalFloat(o, op, "stepDown"), sweep = OptionalFloat(o, op, "sweep");
            MoverBody? body = null;
            if (Get(o, op, "body").ValueKind != JsonValueKind.Null)
            {
                float[] size = Floats(o, op, "body", 2);
                body = Checked(op + ".body", () => new MoverBody(size[0], size[1]));
            }

            (bool slope, bool doors, bool vertical, bool footing, bool edge) =
                (Bool(o, op, "walkableSlope"), Bool(o, op, "doorsOnly"), Bool(o, op, "vertical"), Bool(o, op, "footing"), Bool(o, op, "edgeSlide"));
            MovementOptions options = Checked(op, () => new MovementOptions
            {
                StepDownHeight = stepDown, WalkableSlope = slope, SweepStepLength = sweep, DoorsOnly = doors, Body = body,
                Vertical = vertical, Footing = footing, EdgeSlide = edge,
            });
            return new MoveRequest(Vector(e, at, "position"), Hex(e, at, "cell"), Vector(e, at, "delta"), Float(e, at, "step"))
            {
                Options = options, MoverId = Hex(e, at, "mover"), WithReport = Bool(e, at, "report"),
            };
        }

        private CaptureAnswer MoveAnswer(JsonElement e, int span)
        {
            const string at = "answer";
            Known(e, at, "position", "cell", "onGround", "outcome", "normal", "floor", "wall", "touchedCount", "touched", "commit");
            var answer = new ResolveResult(Vector(e, at, "position"), Hex(e, at, "cell"), Bool(e, at, "onGround"))
            {
                Outcome = Name<ResolveOutcome>(e, at, "outcome"), SurfaceNormal = Vector(e, at, "normal"),
            };
            int count = Int(e, at, "touchedCount");
            JsonElement touched = Array(e, at, "touched");
            if (count < 0 || touched.GetArrayLength() != Math.Min(count, span))
            {
                throw Error("answer.touched", $"{touched.GetArrayLength()} ids for {count} touched in a span of {span}: the ids written are min(touchedCount, span).");
            }

            uint[] ids = [.. touched.EnumerateArray().Select((id, i) => HexValue(id, $"answer.touched[{i}]"))];
            var report = new MoveReport(Contact(e, "floor"), Contact(e, "wall"));
            return new CaptureAnswer(Move: new MoveResult(answer, report, count, Long(e, at, "commit")), Touched: ids);
        }

        private SurfaceContact Contact(JsonElement parent, string name)
        {
            JsonElement e = Get(parent, "answer", name);
            string at = "answer." + name;
            Known(e, at, "kind", "id", "normal");
            return new SurfaceContact(Name<SurfaceKind>(e, at, "kind"), Hex(e, at, "id"), Vector(e, at, "normal"));
        }

        private CastRequest CastRequest(JsonElement e)
        {
            const string at = "request";
            Known(e, at, "from", "cell", "delta", "radius", "filter", "mover");
            uint filter = Hex(e, at, "filter");
            if ((filter & ~(uint)(CastFilter.IgnoreCreatures | CastFilter.SolidOnly)) != 0)
            {
                throw Error("request.filter", $"0x{filter:X8} has bits that are not a cast's filters (IgnoreCreatures 0x1, SolidOnly 0x2).");
            }

            return new CastRequest(Vector(e, at, "from"), Hex(e, at, "cell"), Vector(e, at, "delta"))
            {
                Options = new CastOptions(Float(e, at, "radius"), (CastFilter)filter), MoverId = Hex(e, at, "mover"),
            };
        }

        private CastHit CastHit(JsonElement e)
        {
            const string at = "answer";
            Known(e, at, "hit", "fraction", "position", "point", "normal", "kind", "id", "cell");
            return new CastHit(
                Bool(e, at, "hit"), Float(e, at, "fraction"), Vector(e, at, "position"), Vector(e, at, "point"), Vector(e, at, "normal"),
                Name<SurfaceKind>(e, at, "kind"), Hex(e, at, "id"), Hex(e, at, "cell"));
        }

        private static string PathOf(string parent, string name) => parent.Length == 0 ? name : $"{parent}.{name}";

        private CaptureFormatException Error(string field, string what) => new(_number, field, what);

        private void Known(JsonElement e, string at, params string[] names)
        {
            foreach (JsonProperty property in e.EnumerateObject())
            {
                if (System.Array.IndexOf(names, property.Name) < 0)
                {
                    throw Error(PathOf(at, property.Name), $"unknown field (this object has {string.Join(", ", names)}).");
                }
            }
        }

        private JsonElement Get(JsonElement e, string at, string name)
        {
            if (e.ValueKind != JsonValueKind.Object)
            {
                throw Error(at, $"expected an object, found {e.ValueKind}.");
            }

            return e.TryGetProperty(name, out JsonElement value) ? value : throw Error(PathOf(at, name), "missing.");
        }

        private JsonElement Typed(JsonElement e, string at, string name, JsonValueKind kind, string what)
        {
            JsonElement value = Get(e, at, name);
            return value.ValueKind == kind ? value : throw Error(PathOf(at, name), $"expected {what}, found {value.ValueKind}.");
        }

        private string Text(JsonElement e, string at, string name) => Typed(e, at, name, JsonValueKind.String, "a string").GetString()!;

        private bool Bool(JsonElement e, string at, string name)
        {
            JsonElement value = Get(e, at, name);
            return value.ValueKind is JsonValueKind.True or JsonValueKind.False ? value.GetBoolean() : throw Error(PathOf(at, name), $"expected true or false, found {value.ValueKind}.");
        }

        private long Long(JsonElement e, string at, string name) =>
            Typed(e, at, name, JsonValueKind.Number, "a whole number").TryGetInt64(out long n) ? n : throw Error(PathOf(at, name), "expected a whole number.");

        private int Int(JsonElement e, string at, string name) =>
            Typed(e, at, name, JsonValueKind.Number, "a whole number").TryGetInt32(out int n) ? n : throw Error(PathOf(at, name), "expected a whole number (32 bits).");

        private JsonElement Array(JsonElement e, string at, string name) => Typed(e, at, name, JsonValueKind.Array, "an array");

        private uint Hex(JsonElement e, string at, string name) => HexValue(Get(e, at, name), PathOf(at, name));

        private uint HexValue(JsonElement value, string field)
        {
            string? text = value.ValueKind == JsonValueKind.String ? value.GetString() : null;
            return text is { Length: 10 } && text.StartsWith("0x", StringComparison.Ordinal)
                && uint.TryParse(text.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out uint n)
                ? n
                : throw Error(field, $"expected \"0x\" and 8 hex digits, found {value.GetRawText()}.");
        }

        private float Float(JsonElement e, string at, string name) => FloatValue(Get(e, at, name), PathOf(at, name));

        private float FloatValue(JsonElement value, string field)
        {
            string? text = value.ValueKind == JsonValueKind.String ? value.GetString() : null;
            return text is { Length: 8 } && uint.TryParse(text, NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out uint bits)
                ? BitConverter.UInt32BitsToSingle(bits)
                : throw Error(field, $"expected a float's IEEE bits, 8 hex digits, found {value.GetRawText()}.");
        }

        private float? OptionalFloat(JsonElement e, string at, string name) =>
            Get(e, at, name).ValueKind == JsonValueKind.Null ? null : Float(e, at, name);

        private float[] Floats(JsonElement e, string at, string name, int count)
        {
            JsonElement array = Array(e, at, name);
            string field = PathOf(at, name);
            if (array.GetArrayLength() != count)
            {
                throw Error(field, $"expected {count} floats, found {array.GetArrayLength()}.");
            }

            var values = new float[count];
            for (int i = 0; i < count; i++)
            {
                values[i] = FloatValue(array[i], $"{field}[{i}]");
            }

            return values;
        }

        private Vector3 Vector(JsonElement e, string at, string name)
        {
            float[] v = Floats(e, at, name, 3);
            return new Vector3(v[0], v[1], v[2]);
        }

        private Quaternion Quaternion(JsonElement e, string at, string name)
        {
            float[] q = Floats(e, at, name, 4);
            return new Quaternion(q[0], q[1], q[2], q[3]);
        }

        private T Name<T>(JsonElement e, string at, string name)
            where T : struct, Enum
        {
            string text = Text(e, at, name);
            return System.Array.IndexOf(Enum.GetNames<T>(), text) >= 0
                ? Enum.Parse<T>(text)
                : throw Error(PathOf(at, name), $"\"{text}\" is not one of {string.Join(", ", Enum.GetNames<T>())}.");
        }

        private T Checked<T>(string field, Func<T> make)
        {
            try
            {
                return make();
            }
            catch (ArgumentException e)
            {
                throw Error(field, e.Message);
            }
        }
    }
}
