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
        Scene scene = SceneReader.ReadDefault();
        HoltburgWorld world = scene.CreateWorld();
        WalkRecord record = SceneRunner.Run(scene, world, maxFrames: 1);
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

    [Fact]
    public void Build_WithABody_DrawsItsClearanceWhereItTouchedAWall()
    {
        var world = new HoltburgWorld();
        Scene scene = SceneReader.Parse("""
            { "name": "east wall", "start": { "position": [134, 5.15] }, "effects": "player",
              "legs": [ { "name": "in", "to": [137.2, 5.15] }, { "name": "room", "to": [139, 10] },
                        { "name": "into the east wall", "to": [152, 16], "seconds": 2.5 } ] }
            """, "test");
        WalkRecord record = SceneRunner.Run(scene, world);
        int[] touched = record.Samples.Where(s => s.Slide is { Z: 0f } || s.Refusal == ResolveOutcome.Wall).Select(s => s.Frame).ToArray();
        touched.Should().HaveCountGreaterThan(20, "the body slides along the east wall");

        XDocument svg = WalkSvg.Build(record, world);

        XElement[] circles = svg.Descendants(Svg + "g").Single(g => (string?)g.Attribute("id") == "body-clearance").Elements(Svg + "circle").ToArray();
        circles.Should().HaveCountGreaterThan(5);
        int[] frames = circles.Select(c => int.Parse(((string)c.Element(Svg + "title")!).Split(' ', ':')[1], CultureInfo.InvariantCulture)).ToArray();
        frames.Should().BeSubsetOf(touched, "a circle only where the engine answered a slide along a wall or a wall");
        frames.Should().Contain(touched[0]).And.BeInAscendingOrder();

        // The map is x' = a + s·x, y' = b − s·y: fit it on the first and last circles, then every circle
        // is centred on its frame's feet and its radius is the body's, 0.48 m, to that scale.
        Vector2 Centre(XElement c) => new(Number(c, "cx"), Number(c, "cy"));
        Vector3 p0 = record.Samples[frames[0]].Position, p1 = record.Samples[frames[^1]].Position;
        float scale = (Centre(circles[^1]).Y - Centre(circles[0]).Y) / (p0.Y - p1.Y);
        scale.Should().BeGreaterThan(1f, $"the slide runs north, from {p0} to {p1}");
        float a = Centre(circles[0]).X - (scale * p0.X), b = Centre(circles[0]).Y + (scale * p0.Y);
        for (int i = 0; i < circles.Length; i++)
        {
            Vector3 feet = record.Samples[frames[i]].Position;
            Vector2.Distance(Centre(circles[i]), new Vector2(a + (scale * feet.X), b - (scale * feet.Y))).Should().BeLessThan(0.05f, $"circle {i} (frame {frames[i]}) on the feet {feet}");
            Number(circles[i], "r").Should().BeApproximately(MoverBody.Player.Radius * scale, 0.01f, $"circle {i}: the body's radius at {scale} px per metre");
        }

        // The east wall (x = 142.1) is one radius from the centres: the circles touch it.
        float wall = a + (scale * 142.1f);
        circles.Where((c, i) => record.Samples[frames[i]].CellId == 0xA9B40143u && record.Samples[frames[i]].Slide is { X: < -0.99f })
            .Should().HaveCountGreaterThan(5, "the circles along the east wall").And.OnlyContain(c => MathF.Abs(Number(c, "cx") + Number(c, "r") - wall) < 0.05f, $"the east wall is drawn at x' = {wall}");
        svg.Descendants(Svg + "text").Select(t => t.Value).Should().Contain(t => t.StartsWith("body's clearance where it touched a wall", StringComparison.Ordinal), "the legend names the mark");

        XDocument point = WalkSvg.Build(SceneRunner.Run(scene with { Effects = MovementOptions.Player with { Body = null } }, world), world);
        point.Descendants(Svg + "g").Should().NotContain(g => (string?)g.Attribute("id") == "body-clearance", "a point mover has no body to draw");
    }

    private static float Number(XElement element, string attribute) => float.Parse((string)element.Attribute(attribute)!, CultureInfo.InvariantCulture);

    private static Vector2[] Points(string points) =>
        points.Split(' ', StringSplitOptions.RemoveEmptyEntries)
            .Select(p => p.Split(','))
            .Select(xy => new Vector2(float.Parse(xy[0], CultureInfo.InvariantCulture), float.Parse(xy[1], CultureInfo.InvariantCulture)))
            .ToArray();
}
