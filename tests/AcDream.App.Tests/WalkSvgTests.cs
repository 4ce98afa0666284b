using System.Globalization;
using System.Numerics;
using System.Xml.Linq;
using AcDream.App.Scenes;
using AcDream.App.World;
using AcDream.Core.Physics;

namespace AcDream.App.Tests;

public class WalkSvgTests
{
    private static readonly XNamespace Svg = "http://www.w3.org/2000/svg";

    [Fact]
    public void Build_Floors_AreTheEnginesFloorTrianglesOfTheCells()
    {
        var world = new HoltburgWorld();
        WalkRecord record = SceneRunner.Run(SceneReader.ReadDefault(), world, maxFrames: 1);
        var frame = new PhysicsEngine(HoltburgWorld.Holtburg);
        List<Vector3[]> expected = world.CellSurfaces
            .SelectMany(c => c.GetFloorTriangles().Select(t => new[] { t.A, t.B, t.C }.Select(v => frame.ToWorld(c.CellId, v)).ToArray()))
            .ToList();

        XDocument svg = WalkSvg.Build(record, world);

        List<Vector2[]> drawn = svg.Descendants(Svg + "g").Single(g => (string?)g.Attribute("id") == "floors")
            .Elements(Svg + "polygon").Select(p => Points((string)p.Attribute("points")!)).ToList();
        expected.Should().HaveCountGreaterThan(22, "every cell has floor triangles");
        drawn.Should().HaveCount(expected.Count, "one polygon per floor triangle the engine samples");
        drawn.Should().OnlyContain(p => p.Length == 3, "triangles");

        // The map is x' = a + s·x, y' = b − s·y (north up); fit it on two far-apart vertices, check every vertex.
        Vector3 first = expected[0][0];
        int far = expected.FindIndex(t => MathF.Abs(t[0].X - first.X) > 10f);
        far.Should().BePositive("the two buildings are more than 10 m apart");
        float scale = (drawn[far][0].X - drawn[0][0].X) / (expected[far][0].X - first.X);
        scale.Should().BePositive();
        float a = drawn[0][0].X - (scale * first.X), b = drawn[0][0].Y + (scale * first.Y);
        for (int i = 0; i < expected.Count; i++)
        {
            for (int k = 0; k < 3; k++)
            {
                var mapped = new Vector2(a + (scale * expected[i][k].X), b - (scale * expected[i][k].Y));
                Vector2.Distance(mapped, drawn[i][k]).Should().BeLessThan(0.05f, $"triangle {i} vertex {k}: engine {expected[i][k]} maps to {mapped}, drawn at {drawn[i][k]}");
            }
        }
    }

    private static Vector2[] Points(string points) =>
        points.Split(' ', StringSplitOptions.RemoveEmptyEntries)
            .Select(p => p.Split(','))
            .Select(xy => new Vector2(float.Parse(xy[0], CultureInfo.InvariantCulture), float.Parse(xy[1], CultureInfo.InvariantCulture)))
            .ToArray();
}
