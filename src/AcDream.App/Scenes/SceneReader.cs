using System.Globalization;
using System.Numerics;
using System.Reflection;
using System.Text.Json;
using AcDream.App.Movement;
using AcDream.App.World;
using AcDream.Core.Physics;

namespace AcDream.App.Scenes;

/// <summary>Reads scene files (JSON, <c>docs/scenes.md</c>), checking every field.</summary>
internal static class SceneReader
{
    /// <summary>Resource name of the embedded default scene (<c>Scenes/holtburg-walk.json</c>).</summary>
    public const string DefaultResource = "scenes/holtburg-walk.json";

    /// <summary>Default time limit of a point leg, seconds.</summary>
    public const float DefaultPointLegSeconds = 60f;

    /// <summary>Largest scene file read, bytes: 1 MiB.</summary>
    public const int MaxFileBytes = 1024 * 1024;

    /// <summary>Longest leg, seconds.</summary>
    public const float MaxLegSeconds = 600f;

    /// <summary>Largest jump skill a leg may give (the game's skills stay far below it).</summary>
    public const float MaxJumpSkill = 10_000f;

    /// <summary>How far a start may be from the centre landblock's middle (96, 96), metres, along X and along Y: the 3 × 3 landblocks around Holtburg and one more ring (the world is bigger, the walk is not).</summary>
    public const float MaxStartDistance = 2 * PhysicsConstants.LandblockSize;

    /// <summary>Most creatures a scene may have.</summary>
    public const int MaxCreatures = 256;

    /// <summary>Farthest a creature may wander from its home, metres.</summary>
    public const float MaxWander = 50f;

    /// <summary>Most pointer rays a scene may have.</summary>
    public const int MaxPointers = 64;

    private static readonly string[] SceneFields = ["name", "world", "objects", "start", "legs", "notes", "effects", "creatures", "doors", "pointers"];
    private static readonly string[] CreatureFields = ["at", "wander", "seed"];
    private static readonly string[] PointerFields = ["name", "afterLeg", "from", "towards"];
    /// <summary>Largest body radius a scene may give, metres.</summary>
    public const float MaxBodyRadius = 10f;

    /// <summary>Largest body height a scene may give, metres.</summary>
    public const float MaxBodyHeight = 100f;

    private static readonly string[] EffectFields = ["stepDownHeight", "walkableSlope", "sweepStepLength", "doorsOnly", "body", "vertical", "footing", "edgeSlide"];
    private static readonly string[] BodyFields = ["radius", "height"];
    private static readonly string[] StartFields = ["position", "heading"];
    private static readonly string[] LegFields = ["name", "to", "forward", "strafe", "turn", "run", "backward", "seconds", "jump", "jumpSkill", "open", "close"];

    /// <summary>The embedded default scene.</summary>
    public static Scene ReadDefault()
    {
        using Stream stream = Assembly.GetExecutingAssembly().GetManifestResourceStream(DefaultResource)
            ?? throw new InvalidOperationException($"the program lacks its embedded resource {DefaultResource}.");
        using var reader = new StreamReader(stream);
        return Parse(reader.ReadToEnd(), "embedded default (src/AcDream.App/Scenes/holtburg-walk.json)");
    }

    /// <summary>Reads a scene file of at most <see cref="MaxFileBytes"/>.</summary>
    /// <exception cref="SceneFormatException">The file cannot be read, is too large, or is not a valid scene.</exception>
    public static Scene ReadFile(string path)
    {
        string text;
        try
        {
            // Read at most one byte past the limit, whatever length the file reports (/dev/zero says 0).
            var bytes = new byte[MaxFileBytes + 1];
            int length = 0;
            using (var stream = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.Read, bufferSize: 1, FileOptions.SequentialScan))
            {
                for (int read; length < bytes.Length && (read = stream.Read(bytes, length, bytes.Length - length)) > 0;)
                {
                    length += read;
                }
            }

            if (length > MaxFileBytes)
            {
                throw new SceneFormatException($"{path}: the scene file is larger than {MaxFileBytes / (1024 * 1024)} MiB ({MaxFileBytes} bytes), the limit");
            }

            using var reader = new StreamReader(new MemoryStream(bytes, 0, length), detectEncodingFromByteOrderMarks: true);
            text = reader.ReadToEnd();
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
        {
            throw new SceneFormatException($"{path}: cannot read the scene file ({e.Message})");
        }

        return Parse(text, path);
    }

    /// <summary>Parses scene text; <paramref name="source"/> names it in errors.</summary>
    /// <exception cref="SceneFormatException">The text is not a valid scene.</exception>
    public static Scene Parse(string json, string source)
    {
        JsonDocument document;
        try
        {
            document = JsonDocument.Parse(json, new JsonDocumentOptions { CommentHandling = JsonCommentHandling.Skip, AllowTrailingCommas = true });
        }
        catch (JsonException e)
        {
            throw new SceneFormatException($"{source}: not valid JSON (line {e.LineNumber + 1}, byte {e.BytePositionInLine + 1}): {e.Message}");
        }

        using (document)
        {
            var context = new Context(source);
            JsonElement root = document.RootElement;
            context.RequireObject(root, "(top level)", SceneFields);
            string name = context.RequireString(root, "name", "name");
            JsonElement start = context.Require(root, "start", "start");
            context.RequireObject(start, "start", StartFields);
            Vector2 position = context.RequirePoint(start, "position", "start.position");
            if (MathF.Abs(position.X - 96f) > MaxStartDistance || MathF.Abs(position.Y - 96f) > MaxStartDistance)
            {
                throw context.Error("start.position", start.GetProperty("position"), $"must be within {MaxStartDistance} m of the centre landblock's middle (96, 96)");
            }

            float heading = context.OptionalNumber(start, "heading", "start.heading", 0f, -360f, 360f);
            MovementOptions effects = root.TryGetProperty("effects", out JsonElement effectsElement) ? ReadEffects(context, effectsElement) : default;
            string world = HoltburgWorld.Worlds.Holtburg;
            if (root.TryGetProperty("world", out JsonElement worldElement))
            {
                world = worldElement.ValueKind == JsonValueKind.String && worldElement.GetString() is HoltburgWorld.Worlds.Holtburg or HoltburgWorld.Worlds.Staircase
                    ? worldElement.GetString()!
                    : throw context.Error("world", worldElement, $"must be \"{HoltburgWorld.Worlds.Holtburg}\" or \"{HoltburgWorld.Worlds.Staircase}\"");
            }

            List<string> doors = ReadNames(context, root, "doors", HoltburgWorld.DoorSets, world, "door");
            JsonElement legsElement = context.Require(root, "legs", "legs");
            if (legsElement.ValueKind != JsonValueKind.Array || legsElement.GetArrayLength() == 0)
            {
                throw context.Error("legs", legsElement, "must be a non-empty array of legs");
            }

            var legs = new List<SceneLeg>();
            int index = 0;
            foreach (JsonElement leg in legsElement.EnumerateArray())
            {
                legs.Add(ReadLeg(context, leg, $"legs[{index++}]", doors));
            }

            var notes = new List<string>();
            if (root.TryGetProperty("notes", out JsonElement notesElement))
            {
                if (notesElement.ValueKind != JsonValueKind.Array)
                {
                    throw context.Error("notes", notesElement, "must be an array of strings");
                }

                int n = 0;
                foreach (JsonElement note in notesElement.EnumerateArray())
                {
                    notes.Add(note.ValueKind == JsonValueKind.String ? note.GetString()! : throw context.Error($"notes[{n}]", note, "must be a string"));
                    n++;
                }
            }


            List<string> objects = ReadNames(context, root, "objects", HoltburgWorld.ObjectSets, world, "object set");
            List<SceneCreature> creatures = ReadCreatures(context, root);
            List<ScenePointer> pointers = ReadPointers(context, root, legs.Count);
            return new Scene(name, source, position, heading, legs, notes, effects, world, objects, creatures, doors, pointers);
        }
    }

    /// <summary>
    /// A list of names of the world's sets (<c>"objects"</c>, <c>"doors"</c>; <paramref name="what"/> names one): each one of <paramref name="sets"/> whose
    /// world is <paramref name="world"/>, at most once; empty when the field is absent.
    /// </summary>
    private static List<string> ReadNames(Context context, JsonElement root, string field, IReadOnlyDictionary<string, string> sets, string world, string what)
    {
        var names = new List<string>();
        if (!root.TryGetProperty(field, out JsonElement element))
        {
            return names;
        }

        if (element.ValueKind != JsonValueKind.Array)
        {
            throw context.Error(field, element, $"must be an array of {what} names");
        }

        int n = 0;
        foreach (JsonElement set in element.EnumerateArray())
        {
            string? text = set.ValueKind == JsonValueKind.String ? set.GetString() : null;
            if (text is null || !sets.TryGetValue(text, out string? home) || home != world)
            {
                string allowed = string.Join(", ", sets.Where(s => s.Value == world).Select(s => $"\"{s.Key}\""));
                throw context.Error($"{field}[{n}]", set, $"must be one of the {world} world's {what}s ({(allowed.Length > 0 ? allowed : "it has none")})");
            }

            if (names.Contains(text))
            {
                throw context.Error($"{field}[{n}]", set, "is listed twice");
            }

            names.Add(text);
            n++;
        }

        return names;
    }

    /// <summary>
    /// <c>"creatures"</c>: at most <see cref="MaxCreatures"/>, each <c>{ "at": [x, y], "wander": metres, "seed": n }</c>:
    /// <c>at</c> required, within <see cref="MaxStartDistance"/> of (96, 96) as the start; <c>wander</c> 0..<see cref="MaxWander"/>,
    /// default 0 (it stands); <c>seed</c> a whole number ≥ 0, default the creature's number (1 for the first).
    /// </summary>
    private static List<SceneCreature> ReadCreatures(Context context, JsonElement root)
    {
        var creatures = new List<SceneCreature>();
        if (!root.TryGetProperty("creatures", out JsonElement element))
        {
            return creatures;
        }

        if (element.ValueKind != JsonValueKind.Array || element.GetArrayLength() > MaxCreatures)
        {
            throw context.Error("creatures", element, $"must be an array of at most {MaxCreatures} creatures");
        }

        foreach (JsonElement creature in element.EnumerateArray())
        {
            string path = $"creatures[{creatures.Count}]";
            context.RequireObject(creature, path, CreatureFields);
            Vector2 at = context.RequirePoint(creature, "at", $"{path}.at");
            if (MathF.Abs(at.X - 96f) > MaxStartDistance || MathF.Abs(at.Y - 96f) > MaxStartDistance)
            {
                throw context.Error($"{path}.at", creature.GetProperty("at"), $"must be within {MaxStartDistance} m of the centre landblock's middle (96, 96)");
            }

            float wander = context.OptionalNumber(creature, "wander", $"{path}.wander", 0f, 0f, MaxWander);
            float seed = context.OptionalNumber(creature, "seed", $"{path}.seed", creatures.Count + 1, 0f, int.MaxValue);
            if (seed != MathF.Floor(seed))
            {
                throw context.Error($"{path}.seed", creature.GetProperty("seed"), "must be a whole number");
            }

            creatures.Add(new SceneCreature(at, wander, (int)Math.Min(seed, int.MaxValue)));
        }

        return creatures;
    }

    /// <summary>
    /// <c>"pointers"</c>: at most <see cref="MaxPointers"/>, each <c>{ "name": text, "afterLeg": n, "from": [x, y, z], "towards": [x, y, z] }</c>,
    /// all required: <c>afterLeg</c> a leg's number (1 to the number of legs); <c>from</c> within <see cref="MaxStartDistance"/>
    /// of (96, 96) along X and Y, as the start; <c>towards</c> another point.
    /// </summary>
    private static List<ScenePointer> ReadPointers(Context context, JsonElement root, int legCount)
    {
        var pointers = new List<ScenePointer>();
        if (!root.TryGetProperty("pointers", out JsonElement element))
        {
            return pointers;
        }

        if (element.ValueKind != JsonValueKind.Array || element.GetArrayLength() > MaxPointers)
        {
            throw context.Error("pointers", element, $"must be an array of at most {MaxPointers} pointer rays");
        }

        foreach (JsonElement pointer in element.EnumerateArray())
        {
            string path = $"pointers[{pointers.Count}]";
            context.RequireObject(pointer, path, PointerFields);
            string name = context.RequireString(pointer, "name", $"{path}.name");
            context.Require(pointer, "afterLeg", $"{path}.afterLeg");
            float leg = context.OptionalNumber(pointer, "afterLeg", $"{path}.afterLeg", 0f, 1f, legCount);
            if (leg != MathF.Floor(leg))
            {
                throw context.Error($"{path}.afterLeg", pointer.GetProperty("afterLeg"), "must be a whole number");
            }

            Vector3 from = context.RequirePoint3(pointer, "from", $"{path}.from");
            if (MathF.Abs(from.X - 96f) > MaxStartDistance || MathF.Abs(from.Y - 96f) > MaxStartDistance)
            {
                throw context.Error($"{path}.from", pointer.GetProperty("from"), $"must be within {MaxStartDistance} m of the centre landblock's middle (96, 96)");
            }

            Vector3 towards = context.RequirePoint3(pointer, "towards", $"{path}.towards");
            if (towards == from)
            {
                throw context.Error($"{path}.towards", pointer.GetProperty("towards"), "must differ from \"from\" (it gives the ray's direction)");
            }

            pointers.Add(new ScenePointer(name, (int)leg, from, towards));
        }

        return pointers;
    }

    /// <summary><c>"effects"</c>: <c>"literal"</c>, <c>"player"</c> (with the player's body), or an object naming each effect.</summary>
    private static MovementOptions ReadEffects(Context context, JsonElement element)
    {
        if (element.ValueKind == JsonValueKind.String)
        {
            return element.GetString() switch
            {
                "literal" => MovementOptions.Literal,
                "player" => MovementOptions.Player,
                _ => throw context.Error("effects", element, "must be \"literal\", \"player\" or an object of effects"),
            };
        }

        context.RequireObject(element, "effects", EffectFields);
        return new MovementOptions
        {
            StepDownHeight = element.TryGetProperty("stepDownHeight", out _) ? context.OptionalNumber(element, "stepDownHeight", "effects.stepDownHeight", 0f, 0f, 1000f) : null,
            WalkableSlope = context.OptionalBool(element, "walkableSlope", "effects.walkableSlope"),
            SweepStepLength = element.TryGetProperty("sweepStepLength", out _) ? context.OptionalNumber(element, "sweepStepLength", "effects.sweepStepLength", 1f, 0.01f, 100f) : null,
            DoorsOnly = context.OptionalBool(element, "doorsOnly", "effects.doorsOnly"),
            Vertical = context.OptionalBool(element, "vertical", "effects.vertical"),
            Footing = context.OptionalBool(element, "footing", "effects.footing"),
            EdgeSlide = context.OptionalBool(element, "edgeSlide", "effects.edgeSlide"),
            Body = element.TryGetProperty("body", out JsonElement body) ? ReadBody(context, body) : null,
        };
    }

    /// <summary>
    /// <c>"effects.body"</c>: <c>"player"</c> (<see cref="MoverBody.Player"/>), <c>null</c> (a point, as
    /// when it is absent), or <c>{ "radius": r, "height": h }</c> in metres, r in (0, <see cref="MaxBodyRadius"/>],
    /// h in (0, <see cref="MaxBodyHeight"/>].
    /// </summary>
    private static MoverBody? ReadBody(Context context, JsonElement element)
    {
        switch (element.ValueKind)
        {
            case JsonValueKind.Null:
                return null;
            case JsonValueKind.String when element.GetString() == "player":
                return MoverBody.Player;
            case JsonValueKind.Object:
                context.RequireObject(element, "effects.body", BodyFields);
                foreach (string field in BodyFields)
                {
                    context.Require(element, field, $"effects.body.{field}");
                }

                float radius = context.OptionalNumber(element, "radius", "effects.body.radius", 0f, float.Epsilon, MaxBodyRadius);
                float height = context.OptionalNumber(element, "height", "effects.body.height", 0f, float.Epsilon, MaxBodyHeight);
                return new MoverBody(radius, height);
            default:
                throw context.Error("effects.body", element, "must be \"player\", null (a point) or { \"radius\": metres, \"height\": metres }");
        }
    }

    private static SceneLeg ReadLeg(Context context, JsonElement leg, string path, List<string> doors)
    {
        context.RequireObject(leg, path, LegFields);
        string name = context.RequireString(leg, "name", $"{path}.name");
        string? open = ReadDoor("open"), close = ReadDoor("close");
        if (open is not null && close is not null)
        {
            throw context.Error(path, leg, "has \"open\" and \"close\"; a leg opens a door or closes one");
        }
        bool run = context.OptionalBool(leg, "run", $"{path}.run");
        bool backward = context.OptionalBool(leg, "backward", $"{path}.backward");
        bool jump = context.OptionalBool(leg, "jump", $"{path}.jump");
        float skill = context.OptionalNumber(leg, "jumpSkill", $"{path}.jumpSkill", PlayerMovementMode.DefaultJumpSkill, 0f, MaxJumpSkill);
        if (skill != MathF.Floor(skill))
        {
            throw context.Error($"{path}.jumpSkill", leg.GetProperty("jumpSkill"), "must be a whole number");
        }

        bool hasIntent = leg.TryGetProperty("forward", out _) || leg.TryGetProperty("strafe", out _) || leg.TryGetProperty("turn", out _);
        if (leg.TryGetProperty("to", out _))
        {
            if (hasIntent)
            {
                throw context.Error(path, leg, "has \"to\" and an intent (forward/strafe/turn); a leg is one or the other");
            }

            Vector2 to = context.RequirePoint(leg, "to", $"{path}.to");
            float limit = context.OptionalNumber(leg, "seconds", $"{path}.seconds", DefaultPointLegSeconds, float.Epsilon, MaxLegSeconds);
            return new SceneLeg(name, to, 0f, 0f, 0f, run, backward, limit, jump, (int)skill, open, close);
        }

        if (leg.TryGetProperty("backward", out JsonElement backwardElement))
        {
            throw context.Error($"{path}.backward", backwardElement, "applies only to a leg with \"to\" (use \"forward\": -1 here)");
        }

        if (!hasIntent)
        {
            throw context.Error(path, leg, "needs \"to\" (walk to a point) or at least one of \"forward\", \"strafe\", \"turn\"");
        }

        float forward = context.OptionalNumber(leg, "forward", $"{path}.forward", 0f, -1f, 1f);
        float strafe = context.OptionalNumber(leg, "strafe", $"{path}.strafe", 0f, -1f, 1f);
        float turn = context.OptionalNumber(leg, "turn", $"{path}.turn", 0f, -1f, 1f);
        if (!leg.TryGetProperty("seconds", out _))
        {
            throw context.Error($"{path}.seconds", leg, "is required for a leg without \"to\"");
        }

        float seconds = context.OptionalNumber(leg, "seconds", $"{path}.seconds", 0f, float.Epsilon, MaxLegSeconds);
        return new SceneLeg(name, null, forward, strafe, turn, run, false, seconds, jump, (int)skill, open, close);

        string? ReadDoor(string field)
        {
            if (!leg.TryGetProperty(field, out JsonElement door))
            {
                return null;
            }

            return door.ValueKind == JsonValueKind.String && doors.Contains(door.GetString()!)
                ? door.GetString()
                : throw context.Error($"{path}.{field}", door, $"must name one of the scene's \"doors\" ({(doors.Count > 0 ? string.Join(", ", doors.Select(d => $"\"{d}\"")) : "it lists none")})");
        }
    }

    /// <summary>Error helpers that name the source, the field and the value.</summary>
    private sealed class Context(string source)
    {
        public SceneFormatException Error(string field, JsonElement value, string problem)
        {
            string text = value.ValueKind == JsonValueKind.Undefined ? "nothing" : value.GetRawText();
            text = text.ReplaceLineEndings(" ");
            if (text.Length > 80)
            {
                text = string.Concat(text.AsSpan(0, 77), "...");
            }

            return new SceneFormatException($"{source}: field {field}: {problem}; got {text}");
        }

        public void RequireObject(JsonElement element, string path, string[] allowed)
        {
            if (element.ValueKind != JsonValueKind.Object)
            {
                throw Error(path, element, "must be a JSON object");
            }

            var seen = new HashSet<string>(StringComparer.Ordinal);
            foreach (JsonProperty property in element.EnumerateObject())
            {
                string field = path == "(top level)" ? property.Name : $"{path}.{property.Name}";
                if (Array.IndexOf(allowed, property.Name) < 0)
                {
                    throw Error(field, property.Value, $"unknown field (allowed: {string.Join(", ", allowed)})");
                }

                if (!seen.Add(property.Name))
                {
                    throw Error(field, property.Value, "is given twice (a duplicate key; JSON would silently keep the last)");
                }
            }
        }

        public JsonElement Require(JsonElement parent, string name, string path) =>
            parent.TryGetProperty(name, out JsonElement value) ? value : throw Error(path, default, "is missing");

        public string RequireString(JsonElement parent, string name, string path)
        {
            JsonElement value = Require(parent, name, path);
            return value.ValueKind == JsonValueKind.String && !string.IsNullOrWhiteSpace(value.GetString())
                ? value.GetString()!
                : throw Error(path, value, "must be a non-empty string");
        }

        public Vector2 RequirePoint(JsonElement parent, string name, string path)
        {
            JsonElement value = Require(parent, name, path);
            if (value.ValueKind != JsonValueKind.Array || value.GetArrayLength() != 2
                || value[0].ValueKind != JsonValueKind.Number || value[1].ValueKind != JsonValueKind.Number
                || !float.IsFinite(value[0].GetSingle()) || !float.IsFinite(value[1].GetSingle()))
            {
                throw Error(path, value, "must be [x, y], two numbers in metres");
            }

            return new Vector2(value[0].GetSingle(), value[1].GetSingle());
        }

        public Vector3 RequirePoint3(JsonElement parent, string name, string path)
        {
            JsonElement value = Require(parent, name, path);
            if (value.ValueKind != JsonValueKind.Array || value.GetArrayLength() != 3
                || value.EnumerateArray().Any(v => v.ValueKind != JsonValueKind.Number || !float.IsFinite(v.GetSingle())))
            {
                throw Error(path, value, "must be [x, y, z], three numbers in metres");
            }

            return new Vector3(value[0].GetSingle(), value[1].GetSingle(), value[2].GetSingle());
        }

        public bool OptionalBool(JsonElement parent, string name, string path)
        {
            if (!parent.TryGetProperty(name, out JsonElement value))
            {
                return false;
            }

            return value.ValueKind switch
            {
                JsonValueKind.True => true,
                JsonValueKind.False => false,
                _ => throw Error(path, value, "must be true or false"),
            };
        }

        public float OptionalNumber(JsonElement parent, string name, string path, float fallback, float min, float max)
        {
            if (!parent.TryGetProperty(name, out JsonElement value))
            {
                return fallback;
            }

            if (value.ValueKind != JsonValueKind.Number || !float.IsFinite(value.GetSingle()))
            {
                throw Error(path, value, "must be a number");
            }

            float number = value.GetSingle();
            return number >= min && number <= max
                ? number
                : throw Error(path, value, string.Create(CultureInfo.InvariantCulture, $"must be between {(min == float.Epsilon ? "0 (exclusive)" : min.ToString(CultureInfo.InvariantCulture))} and {max}"));
        }
    }
}
