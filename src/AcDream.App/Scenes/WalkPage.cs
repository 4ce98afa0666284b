using System.Text;
using System.Text.Json;
using AcDream.App.World;

namespace AcDream.App.Scenes;

/// <summary>
/// Writes a walk as one self-contained HTML page that scrubs it in 3-D (src/AcDream.App/web/walk-page.html and
/// walk-page.js): the cells' physics polygons, the objects, the doors, a patch of terrain, the creatures, the player's
/// body and the chase camera's eye at each frame, what the frame's steps met, and the route; a timeline and the
/// arrow keys step the frames. three.js (src/AcDream.App/web/three, MIT) goes in as an ES module through an import
/// map of a <c>data:</c> URL, and the walk as JSON (<see cref="WriteData"/>), so the page opens from disk with no
/// server and no network.
/// </summary>
internal static partial class WalkPage
{
    /// <summary>The three.js release inlined (src/AcDream.App/web/three).</summary>
    internal const string ThreeVersion = "0.187.0";

    /// <summary>The page for <paramref name="record"/> run in <paramref name="world"/>.</summary>
    public static string Build(WalkRecord record, HoltburgWorld world)
    {
        // Base64 needs no escaping in JSON or HTML.
        string importMap = "{\"imports\":{\"three\":\"" + DataUrl(Resource("web/three/three.module.min.js")) + "\"}}";

        using var data = new MemoryStream();
        using (var json = new Utf8JsonWriter(data)) // the default encoder escapes '<', '>' and '&': safe inside <script>
        {
            WriteData(json, record, world);
        }

        return Resource("web/walk-page.html")
            .Replace("{{TITLE}}", System.Net.WebUtility.HtmlEncode(record.Scene.Name), StringComparison.Ordinal)
            .Replace("{{IMPORTMAP}}", importMap, StringComparison.Ordinal)
            .Replace("{{SCRIPT}}", Resource("web/walk-page.js"), StringComparison.Ordinal)
            .Replace("{{DATA}}", Encoding.UTF8.GetString(data.ToArray()), StringComparison.Ordinal);
    }

    /// <summary>Writes the page to <paramref name="stream"/> as UTF-8.</summary>
    public static void Write(WalkRecord record, HoltburgWorld world, Stream stream)
    {
        byte[] bytes = new UTF8Encoding(false).GetBytes(Build(record, world));
        stream.Write(bytes);
    }

    private static string DataUrl(string javaScript) => "data:text/javascript;base64," + Convert.ToBase64String(Encoding.UTF8.GetBytes(javaScript));

    private static string Resource(string name)
    {
        using Stream stream = typeof(WalkPage).Assembly.GetManifestResourceStream(name)
            ?? throw new InvalidOperationException($"The page's resource {name} is not embedded in the program.");
        using var reader = new StreamReader(stream, Encoding.UTF8);
        return reader.ReadToEnd();
    }
}
