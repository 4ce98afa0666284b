using System.Globalization;
using System.Numerics;
using System.Text.Json;

namespace AcDream.App.Scenes;

// SceneReader's context: the errors that name the source, the field and the value.
internal static partial class SceneReader
{
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
