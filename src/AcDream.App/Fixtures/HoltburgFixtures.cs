using System.Reflection;

namespace AcDream.App.Fixtures;

/// <summary>The 22 real Holtburg cells (landblock 0xA9B4), read from the program's embedded resources.</summary>
internal static class HoltburgFixtures
{
    private const string Prefix = "holtburg-cells/";

    /// <summary>Reads every embedded cell fixture, in ascending cell id order. Each call returns new objects.</summary>
    public static List<CellFixtureReader.FixtureCell> ReadAll()
    {
        Assembly assembly = typeof(HoltburgFixtures).Assembly;
        var cells = new List<CellFixtureReader.FixtureCell>();
        foreach (string name in assembly.GetManifestResourceNames())
        {
            if (!name.StartsWith(Prefix, StringComparison.Ordinal))
            {
                continue;
            }

            using Stream stream = assembly.GetManifestResourceStream(name)!;
            using var reader = new StreamReader(stream);
            cells.Add(CellFixtureReader.Read(reader.ReadToEnd(), name));
        }

        cells.Sort((a, b) => a.CellId.CompareTo(b.CellId));
        return cells;
    }

    /// <summary>Reads every embedded object fixture (<c>Fixtures/objects/0x*.json</c>), by GfxObj id. Each call returns new objects.</summary>
    public static Dictionary<uint, Core.Dat.GfxObj> ReadObjects()
    {
        Assembly assembly = typeof(HoltburgFixtures).Assembly;
        var objects = new Dictionary<uint, Core.Dat.GfxObj>();
        foreach (string name in assembly.GetManifestResourceNames())
        {
            if (!name.StartsWith("objects/0x", StringComparison.Ordinal))
            {
                continue;
            }

            using Stream stream = assembly.GetManifestResourceStream(name)!;
            using var reader = new StreamReader(stream);
            Core.Dat.GfxObj gfxObj = ObjectFixtureReader.Read(reader.ReadToEnd(), name);
            objects.Add(gfxObj.Id, gfxObj);
        }

        return objects;
    }
}
